#!/usr/bin/env node
// The VS Code extension's TextMate grammar held to mbc's lexer. Each
// golden program is tokenized by vscode-textmate (with vscode-oniguruma,
// the engine VS Code runs grammars with) and by `mbc lsp`'s semantic
// tokens, which come from the lexer. Every token of the lexer must be
// coloured as its class (a G code as a G code, a variable as a variable,
// DPRNT's text as a string...), no character may be left without a scope
// of the grammar's own, and every scope the grammar names must be seen.
//
//   node vscode_grammar.js MBC EXTENSION_DIR PROGRAM_OR_FOLDER...
// EXTENSION_DIR holds the grammar and the packages npm installed for it
// (the build's editors/vscode); a folder stands for its .nc files, within
// it and below.
"use strict";

const fs = require("fs");
const path = require("path");
const { spawn } = require("child_process");

const [mbc, extension, ...given] = process.argv.slice(2);
const modules = path.resolve(extension, "node_modules");
if (!fs.existsSync(path.join(modules, "vscode-textmate"))) {
  console.log("skipped: npm could not fetch vscode-textmate at build time");
  process.exit(77);
}
const programs = given.flatMap(function programsIn(p) {
  if (!fs.statSync(p).isDirectory()) {
    return [p];
  }
  return fs.readdirSync(p).sort().flatMap((name) => {
    const inner = path.join(p, name);
    return fs.statSync(inner).isDirectory() ? programsIn(inner)
         : name.endsWith(".nc") ? [inner] : [];
  });
});
const vsctm = require(path.join(modules, "vscode-textmate"));
const oniguruma = require(path.join(modules, "vscode-oniguruma"));
const grammarPath = path.join(extension, "syntaxes",
                              "fanuc-macro-b.tmLanguage.json");
const ROOT = "source.fanuc-macro-b";
// VS Code leaves longer lines without colours
// (editor.maxTokenizationLineLength), and so does this test.
const MAX_TOKENIZED_LINE = 20000;

// What each class of the server's legend may be coloured as: the prefixes
// of the grammar's scopes.
const CLASSES = {
  keyword: ["keyword.control.", "keyword.operator.word.", "keyword.other."],
  variable: ["variable.other.", "variable.language."],
  number: ["constant.numeric."],
  comment: ["comment."],
  function: ["support.function."],
  property: ["variable.parameter.address."],
  namespace: ["entity.name.function.program."],
  operator: ["keyword.operator.arithmetic.", "keyword.operator.assignment."],
  string: ["string."],
  enumMember: ["entity.name.label."],
};

/// `mbc lsp`'s semantic tokens of each text: [line, start, length, class].
function semanticTokens(texts) {
  return new Promise((resolve, reject) => {
    if (texts.length === 0) {
      resolve([]);
      return;
    }
    const server = spawn(mbc, ["lsp"], { stdio: ["pipe", "pipe", "inherit"] });
    let buffer = Buffer.alloc(0);
    let legend = null;
    const results = new Map();
    const send = (message) => {
      const body = Buffer.from(JSON.stringify(message));
      server.stdin.write(`Content-Length: ${body.length}\r\n\r\n`);
      server.stdin.write(body);
    };
    const received = (message) => {
      if (message.id === 0) {
        legend = message.result.capabilities.semanticTokensProvider.legend;
        send({ jsonrpc: "2.0", method: "initialized", params: {} });
        texts.forEach((text, i) => {
          const uri = `untitled:program${i}.nc`;
          send({ jsonrpc: "2.0", method: "textDocument/didOpen", params: {
            textDocument: { uri, languageId: "fanuc-macro-b", version: 1,
                            text } } });
          send({ jsonrpc: "2.0", id: i + 1,
                 method: "textDocument/semanticTokens/full",
                 params: { textDocument: { uri } } });
        });
      } else if (typeof message.id === "number" && message.id > 0) {
        if (message.error) {
          reject(new Error(JSON.stringify(message.error)));
          return;
        }
        const data = message.result.data;
        const tokens = [];
        let line = 0, start = 0;
        for (let k = 0; k < data.length; k += 5) {
          line += data[k];
          start = data[k] === 0 ? start + data[k + 1] : data[k + 1];
          tokens.push([line, start, data[k + 2], legend.tokenTypes[data[k + 3]]]);
        }
        results.set(message.id - 1, tokens);
        if (results.size === texts.length) {
          send({ jsonrpc: "2.0", id: -1, method: "shutdown" });
          send({ jsonrpc: "2.0", method: "exit" });
          resolve(texts.map((_, i) => results.get(i)));
        }
      }
    };
    server.stdout.on("data", (chunk) => {
      buffer = Buffer.concat([buffer, chunk]);
      for (;;) {
        const header = buffer.indexOf("\r\n\r\n");
        if (header < 0) {
          return;
        }
        const length = Number(/Content-Length: (\d+)/i.exec(
            buffer.subarray(0, header).toString())[1]);
        if (buffer.length < header + 4 + length) {
          return;
        }
        received(JSON.parse(buffer.subarray(header + 4, header + 4 + length)));
        buffer = buffer.subarray(header + 4 + length);
      }
    });
    server.on("exit", (code) => {
      if (results.size < texts.length) {
        reject(new Error(`mbc lsp ended (${code}) before it answered`));
      }
    });
    // Positions in UTF-16, as JavaScript's strings count them.
    send({ jsonrpc: "2.0", id: 0, method: "initialize",
           params: { processId: null, rootUri: null, capabilities: {} } });
  });
}

/// The grammar's scopes: every name it gives a token.
function namedScopes(node, out = new Set()) {
  if (Array.isArray(node)) {
    node.forEach((n) => namedScopes(n, out));
  } else if (node && typeof node === "object") {
    for (const [key, value] of Object.entries(node)) {
      if (key === "name" && typeof value === "string") {
        out.add(value);
      } else {
        namedScopes(value, out);
      }
    }
  }
  return out;
}

async function main() {
  const wasm = fs.readFileSync(
      path.join(modules, "vscode-oniguruma", "release", "onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer);
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async () => vsctm.parseRawGrammar(
        fs.readFileSync(grammarPath, "utf8"), grammarPath),
  });
  const grammar = await registry.loadGrammar(ROOT);
  const named = namedScopes(
      JSON.parse(fs.readFileSync(grammarPath, "utf8")).repository);
  const seen = new Set();

  // Programs whose text is not UTF-8 are read as the lexer reads bytes; the
  // grammar sees what the editor would show, so they are left out.
  const files = programs.filter((p) => {
    const bytes = fs.readFileSync(p);
    return Buffer.from(bytes.toString("utf8"), "utf8").equals(bytes);
  });
  const texts = files.map((p) => fs.readFileSync(p, "utf8"));
  const semantic = await semanticTokens(texts);
  const problems = [];
  texts.forEach((text, i) => {
    const lines = text.split(/\r?\n|\r/);
    // scopes[line][character]: the scopes of each character.
    const scopes = [];
    let stack = vsctm.INITIAL;
    lines.forEach((line, n) => {
      if (line.length > MAX_TOKENIZED_LINE) {
        scopes.push(null);
        return;
      }
      const result = grammar.tokenizeLine(line, stack);
      stack = result.ruleStack;
      const perCharacter = new Array(line.length);
      for (const token of result.tokens) {
        const own = token.scopes.slice(1);
        own.forEach((s) => seen.add(s));
        for (let c = token.startIndex; c < Math.min(token.endIndex, line.length);
             ++c) {
          perCharacter[c] = own;
          if (own.length === 0 && !/\s/.test(line[c])) {
            problems.push(`${files[i]}:${n + 1}:${c + 1}: '${line[c]}' ` +
                          "has no scope of the grammar");
          }
        }
      }
      scopes.push(perCharacter);
    });
    for (const [line, start, length, cls] of semantic[i]) {
      if (scopes[line] === null) {
        continue;
      }
      for (let c = start; c < start + length; ++c) {
        if (/\s/.test(lines[line][c])) {
          continue; // spaces inside a number: "X1 00."
        }
        const own = scopes[line][c] || [];
        if (!own.some((s) => CLASSES[cls].some((p) => s.startsWith(p)))) {
          problems.push(`${files[i]}:${line + 1}:${c + 1}: the lexer's ` +
                        `${cls} '${lines[line].substr(start, length)}' is ` +
                        `coloured ${own.join(" ") || "as nothing"}`);
          break;
        }
      }
    }
  });
  for (const scope of named) {
    if (!seen.has(scope)) {
      problems.push(`no golden program has a token of ${scope}`);
    }
  }
  problems.slice(0, 40).forEach((p) => console.log(p));
  if (problems.length > 0) {
    console.log(`FAIL: ${problems.length} problems in ${texts.length} programs`);
    process.exit(1);
  }
  console.log(`ok: ${texts.length} programs, ${named.size} scopes, ` +
              "every lexer token coloured as its class");
}

main().catch((e) => {
  console.log(`FAIL: ${e.stack || e}`);
  process.exit(1);
});
