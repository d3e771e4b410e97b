// The client of `mbc lsp`: Visual Studio Code starts the server for the
// workspace's Macro B programs and shows what it answers (docs/editors.md).
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

// The files the server reads again when they change: called programs.
const PROGRAMS = "**/*.{nc,cnc,tap,NC,CNC,TAP}";

let client;

/// The settings the user gave, as the server's initialization options:
/// only those given, so that mbc.json's keys hold for the others.
function initializationOptions(config) {
  const options = {};
  const machine = config.get("machine");
  if (machine) {
    options.machine = machine;
  }
  const include = config.get("include");
  if (Array.isArray(include) && include.length > 0) {
    options.include = include;
  }
  return options;
}

function activate(context) {
  const config = vscode.workspace.getConfiguration("mbc");
  const server = { command: config.get("path") || "mbc", args: ["lsp"] };
  client = new LanguageClient("mbc", "mbc", server, {
    documentSelector: [{ language: "fanuc-macro-b" }],
    initializationOptions: initializationOptions(config),
    synchronize: {
      fileEvents: vscode.workspace.createFileSystemWatcher(PROGRAMS),
    },
  });
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
