#!/usr/bin/env node
// The VS Code extension's client, loaded with stand-ins for VS Code's API
// and the language client (VS Code itself is no Debian package): what it
// starts (`mbc lsp`, or the command mbc.path names), for which documents
// (the language its package.json contributes), and which settings it
// passes as initialization options (only those given, so that a
// workspace's mbc.json holds for the rest). The server's side of each is
// tests/lsp_protocol.py's.
//
//   node vscode_extension.js EXTENSION_DIR
"use strict";

const Module = require("module");
const path = require("path");

const extension = path.resolve(process.argv[2]);
const manifest = require(path.join(extension, "package.json"));
let made = null;
let started = 0;
let settings = {};

class LanguageClient {
  constructor(id, name, server, options) {
    made = { id, name, server, options };
  }
  start() {
    started += 1;
    return Promise.resolve();
  }
  stop() {
    return Promise.resolve();
  }
  dispose() {}
}

const vscode = {
  workspace: {
    getConfiguration: (section) => ({
      get: (key) => section === "mbc" ? settings[key] : undefined,
    }),
    createFileSystemWatcher: (glob) => ({ glob }),
  },
};
const load = Module._load;
Module._load = function (request, parent, isMain) {
  if (request === "vscode") {
    return vscode;
  }
  if (request === "vscode-languageclient/node") {
    return { LanguageClient };
  }
  return load.call(this, request, parent, isMain);
};

function expect(condition, what) {
  if (!condition) {
    console.log(`FAIL: ${what}`);
    process.exit(1);
  }
}

async function main() {
  const client = require(path.join(extension, manifest.main));
  const language = manifest.contributes.languages[0];
  const context = { subscriptions: [] };

  settings = { path: "mbc", machine: "", include: [] };
  await client.activate(context);
  expect(made && started === 1, "activate starts a client");
  expect(made.server.command === "mbc" &&
         JSON.stringify(made.server.args) === '["lsp"]',
         `the server is mbc lsp: ${JSON.stringify(made.server)}`);
  expect(made.options.documentSelector[0].language === language.id,
         "the client serves the language the package contributes");
  expect(JSON.stringify(made.options.initializationOptions) === "{}",
         "settings not given are not passed: mbc.json's hold");
  const watched = made.options.synchronize.fileEvents.glob;
  for (const ext of language.extensions) {
    expect(watched.includes(`,${ext.slice(1)},`) ||
           watched.includes(`{${ext.slice(1)},`),
           `the files watched include the language's ${ext}`);
  }
  expect(context.subscriptions.length === 1,
         "the client is disposed of with the extension");
  await client.deactivate();

  settings = { path: "/opt/mbc/bin/mbc", machine: "machines/vmc.json",
               include: ["macros"] };
  await client.activate({ subscriptions: [] });
  expect(made.server.command === "/opt/mbc/bin/mbc", "mbc.path is the command");
  expect(JSON.stringify(made.options.initializationOptions) ===
         '{"machine":"machines/vmc.json","include":["macros"]}',
         `the settings given are passed: ${JSON.stringify(
             made.options.initializationOptions)}`);
  console.log("ok: the extension starts mbc lsp for its language, with the " +
              "settings given");
}

main().catch((e) => {
  console.log(`FAIL: ${e.stack || e}`);
  process.exit(1);
});
