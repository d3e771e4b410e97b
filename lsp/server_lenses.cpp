// The code lenses of the server (see server.h): one per program of a
// document, made at once, and given its run when the editor shows it
// (codeLens/resolve), so that only the programs on screen run; its
// command writes the run's --html view and has the editor open it.
#include <fmt/format.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "lsp/json_params.h"
#include "lsp/server.h"
#include "lsp/uri.h"

namespace mbc::lsp {

using nlohmann::json;

namespace {

/// The program a lens or a command names ("" for an anonymous main).
std::optional<std::string> programOf(const json& data) {
  return text(data, "program");
}

/// The view's file name: the document's and the program's, letters kept.
std::string viewName(const std::string& uri, const std::string& program) {
  std::string name = std::filesystem::path(uri).stem().string() + "-" +
                     (program.empty() ? "main" : program);
  for (char& c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '-') {
      c = '_';
    }
  }
  return name + ".html";
}

} // namespace

Server::~Server() {
  if (!viewFolder_.empty()) {
    std::error_code ignored;
    std::filesystem::remove_all(viewFolder_, ignored);
  }
}

std::string Server::viewFolder() {
  if (viewFolder_.empty()) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "mbc-lsp-XXXXXX").string();
    if (mkdtemp(pattern.data()) != nullptr) {
      viewFolder_ = pattern;
    }
  }
  return viewFolder_;
}

std::optional<json> Server::codeLens(const json& params) {
  Document* doc = document(params);
  if (doc == nullptr) {
    return std::nullopt;
  }
  json out = json::array();
  for (const Program& p : doc->analysis->cu.unit.programs) {
    if (p.file != 0 || p.duplicate) {
      continue;
    }
    out.push_back({{"range", rangeOf(p.range, *doc->analysis, *doc->text)},
                   {"data",
                    {{"uri", doc->text->uri()},
                     {"version", doc->text->version()},
                     {"program", p.number < 0 ? std::string() : p.name}}}});
  }
  return out;
}

Server::Document* Server::lensDocument(const json& lens) {
  const json data = lens.is_object() ? lens.value("data", json()) : json();
  const std::optional<std::string> uri = text(data, "uri");
  const auto it = uri ? documents_.find(*uri) : documents_.end();
  if (it == documents_.end() || !programOf(data) ||
      integer(data, "version", -1) != it->second.text->version()) {
    return nullptr;
  }
  analyse(it->second);
  return &it->second;
}

RunSummary Server::run(Document& doc, const std::string& program,
                       const std::string& html) {
  RunInput input;
  input.path = nameOfUri(doc.text->uri());
  input.text = doc.text->text();
  input.files = doc.analysis->files;
  input.settings = settingsFor(*doc.text);
  input.program = program;
  input.blockBudget = runBlocks_;
  return runProgram(input, html);
}

std::optional<json> Server::codeLensResolve(const json& params) {
  Document* doc = lensDocument(params);
  if (doc == nullptr) {
    return std::nullopt;
  }
  const std::string program = *programOf(params["data"]);
  auto found = doc->runs.find(program);
  if (found == doc->runs.end()) {
    found = doc->runs.emplace(program, run(*doc, program, "")).first;
  }
  json lens = params;
  lens["command"] = {
      {"title", lensTitle(found->second, nameOfUri(doc->text->uri()))},
      {"command", kShowRunCommand},
      {"arguments", {doc->text->uri(), program}}};
  return lens;
}

std::optional<json> Server::executeCommand(const json& params) {
  const json arguments =
      params.is_object() ? params.value("arguments", json()) : json();
  if (text(params, "command") != kShowRunCommand || !arguments.is_array() ||
      arguments.size() != 2 || !arguments[0].is_string() ||
      !arguments[1].is_string()) {
    return std::nullopt;
  }
  const auto it = documents_.find(arguments[0].get<std::string>());
  if (it == documents_.end()) {
    return std::nullopt;
  }
  Document& doc = it->second;
  analyse(doc);
  const std::string program = arguments[1].get<std::string>();
  const std::string folder = viewFolder();
  if (folder.empty()) {
    notify("window/showMessage",
           {{"type", kLogError},
            {"message", "mbc: no temporary folder for the run's view"}});
    return json(nullptr);
  }
  const std::string path = folder + "/" + viewName(doc.text->uri(), program);
  const RunSummary summary = run(doc, program, path);
  if (!summary.failure.empty()) {
    notify("window/showMessage",
           {{"type", kLogError},
            {"message", "mbc: the run has no view: " + summary.failure}});
    return json(nullptr);
  }
  const std::string uri = uriOfPath(path);
  if (showDocument_) {
    ask("window/showDocument", {{"uri", uri}, {"external", true}});
  } else {
    notify("window/showMessage", {{"type", kLogInfo},
                                  {"message", "mbc: the run's view is " + path +
                                                  ": open it in a browser"}});
  }
  return json{{"uri", uri}};
}

} // namespace mbc::lsp
