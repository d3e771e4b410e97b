// The language server (see server.h).
#include "lsp/server.h"

#include <mbc/engine.h>
#include <mbc/runtime.h>
#include <mbc/version.h>

#include <fmt/format.h>

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <set>
#include <thread>

#include "lsp/arguments.h"
#include "lsp/ast_lookup.h"
#include "lsp/completion.h"
#include "lsp/hover.h"
#include "lsp/json_params.h"
#include "lsp/message_stream.h"
#include "lsp/navigation.h"
#include "lsp/semantic_tokens.h"
#include "lsp/uri.h"

namespace mbc::lsp {

using nlohmann::json;

namespace {

/// Messages the reader holds back while more are arriving: a client that
/// never pauses is still served.
constexpr std::size_t kMessagesHeldAtMost = 1024;

/// Why a message cannot be taken as a request or notification, or "".
std::string malformed(const json& message) {
  if (!message.is_object()) {
    return "a message must be a JSON object";
  }
  if (!message.contains("method")) {
    return message.contains("id") ? "" : "a message without a method";
  }
  if (!message["method"].is_string()) {
    return "a method must be a string";
  }
  if (message.contains("id") && !message["id"].is_string() &&
      !message["id"].is_number_integer()) {
    return "an id must be a number or a string";
  }
  return "";
}

} // namespace

void Server::respond(const json& id, json result) {
  send_(
      json{{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}}.dump(
          -1, ' ', false, json::error_handler_t::replace));
}

void Server::ask(const std::string& method, json params) {
  send_(json{{"jsonrpc", "2.0"},
             {"id", fmt::format("mbc-{}", ++asked_)},
             {"method", method},
             {"params", std::move(params)}}
            .dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::fail(const json& id, int code, const std::string& message) {
  send_(json{{"jsonrpc", "2.0"},
             {"id", id},
             {"error", {{"code", code}, {"message", message}}}}
            .dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::notify(const std::string& method, json params) {
  send_(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", params}}.dump(
      -1, ' ', false, json::error_handler_t::replace));
}

void Server::log(int type, const std::string& message) {
  notify("window/logMessage", {{"type", type}, {"message", message}});
}

void Server::problem(const std::string& what) {
  log(kLogError, "mbc lsp: " + what);
}

void Server::handleBatch(const std::vector<std::string>& bodies) {
  std::vector<json> messages;
  for (const std::string& body : bodies) {
    json message = json::parse(body, nullptr, false);
    if (message.is_discarded()) {
      fail(nullptr, kParseError, "the message is not JSON");
      continue;
    }
    if (const std::string why = malformed(message); !why.empty()) {
      fail(message.is_object() ? message.value("id", json()) : json(),
           kInvalidRequest, why);
      continue;
    }
    messages.push_back(std::move(message));
  }
  // What later messages of the batch say of earlier ones.
  std::set<json> cancelled;
  std::map<std::string, std::size_t> lastChange;
  for (std::size_t i = 0; i < messages.size(); ++i) {
    const json& m = messages[i];
    const std::string method = m.value("method", "");
    const json& params = m.contains("params") ? m["params"] : json();
    if (method == "$/cancelRequest" && params.is_object() &&
        params.contains("id")) {
      cancelled.insert(params["id"]);
    }
    if (method == "textDocument/didChange" ||
        method == "textDocument/didClose") {
      if (const std::optional<std::string> uri = documentUri(params)) {
        lastChange[*uri] = i;
      }
    }
  }
  for (std::size_t i = 0; i < messages.size() && !exited_; ++i) {
    const json& m = messages[i];
    bool stale = false;
    if (const std::optional<std::string> uri =
            documentUri(m.value("params", json()))) {
      const auto change = lastChange.find(*uri);
      stale = change != lastChange.end() && change->second > i;
    }
    // A member of the wrong type deep in the parameters ("version": "x")
    // is the client's mistake: said, and the server goes on.
    try {
      dispatch(m, stale, m.contains("id") && cancelled.count(m["id"]) != 0);
    } catch (const json::exception& e) {
      const std::string why =
          fmt::format("{}: a parameter of the wrong type ({})",
                      m.value("method", "?"), e.what());
      if (m.contains("id")) {
        fail(m["id"], kInvalidParams, why);
      } else {
        log(kLogError, "mbc lsp: " + why);
      }
    }
  }
  // One analysis per changed document.
  for (auto& [uri, doc] : documents_) {
    if (!doc.published && !exited_) {
      publish(doc);
    }
  }
}

void Server::dispatch(const json& message, bool stale, bool cancelled) {
  if (!message.contains("method")) {
    return; // a response: the server does not wait for any
  }
  const std::string method = message["method"].get<std::string>();
  const json params = message.value("params", json::object());
  if (!message.contains("id")) {
    notification(method, params);
    return;
  }
  const json& id = message["id"];
  if (cancelled) {
    fail(id, kRequestCancelled, "cancelled");
  } else if (stale && method != "initialize" && method != "shutdown") {
    fail(id, kContentModified,
         "the document changed after the request: ask again");
  } else {
    request(id, method, params);
  }
}

void Server::request(const json& id, const std::string& method,
                     const json& params) {
  if (method == "initialize") {
    if (initialized_) {
      fail(id, kInvalidRequest, "initialize was sent twice");
      return;
    }
    respond(id, initialize(params));
    return;
  }
  if (!initialized_) {
    fail(id, kServerNotInitialized, "initialize comes first");
    return;
  }
  if (shutdown_) {
    fail(id, kInvalidRequest, "the server is shutting down");
    return;
  }
  if (method == "shutdown") {
    shutdown_ = true;
    respond(id, nullptr);
    return;
  }
  using Handler = std::optional<json> (Server::*)(const json&);
  static const std::map<std::string, Handler> kHandlers = {
      {"textDocument/hover", &Server::hover},
      {"textDocument/definition", &Server::definition},
      {"textDocument/documentSymbol", &Server::documentSymbol},
      {"textDocument/codeAction", &Server::codeAction},
      {"textDocument/references", &Server::references},
      {"textDocument/completion", &Server::completion},
      {"workspace/symbol", &Server::workspaceSymbol},
      {"textDocument/inlayHint", &Server::inlayHint},
      {"textDocument/signatureHelp", &Server::signatureHelp},
      {"textDocument/semanticTokens/full", &Server::semanticTokens},
      {"textDocument/codeLens", &Server::codeLens},
      {"codeLens/resolve", &Server::codeLensResolve},
      {"workspace/executeCommand", &Server::executeCommand},
  };
  if (method == "codeLens/resolve" && lensDocument(params) == nullptr) {
    fail(id, kContentModified,
         "the document changed after the lens was made: ask again");
    return;
  }
  const auto handler = kHandlers.find(method);
  if (handler == kHandlers.end()) {
    fail(id, kMethodNotFound, fmt::format("mbc lsp has no method {}", method));
    return;
  }
  if (std::optional<json> result = (this->*handler->second)(params)) {
    respond(id, std::move(*result));
  } else {
    fail(id, kInvalidParams,
         fmt::format("{}: the parameters name no open document or place",
                     method));
  }
}

void Server::notification(const std::string& method, const json& params) {
  if (method == "exit") {
    exited_ = true;
    return;
  }
  if (!initialized_ || shutdown_) {
    return; // dropped, as the protocol says
  }
  const std::optional<std::string> uri = documentUri(params);
  if (method == "workspace/didChangeWatchedFiles") {
    const json changes = params.value("changes", json::array());
    for (const json& change : changes.is_array() ? changes : json::array()) {
      if (const std::optional<std::string> changed = text(change, "uri")) {
        if (const std::optional<std::string> path = pathOfUri(*changed)) {
          fileChanged(*path);
        }
      }
    }
    return;
  }
  if (method == "textDocument/didSave" && uri) {
    if (const std::optional<std::string> path = pathOfUri(*uri)) {
      fileChanged(*path);
    }
    return;
  }
  if (method == "textDocument/didOpen" && uri) {
    const json& item = params["textDocument"];
    const std::optional<std::string> body = text(item, "text");
    if (!body) {
      log(kLogWarning, fmt::format("didOpen of {} without its text", *uri));
      return;
    }
    Document& doc = documents_[*uri];
    doc.text = std::make_unique<TextDocument>(*uri, integer(item, "version", 0),
                                              *body);
    doc.changed();
    return;
  }
  const auto it = uri ? documents_.find(*uri) : documents_.end();
  if (it == documents_.end()) {
    return; // a document not open (or a notification of no document)
  }
  Document& doc = it->second;
  if (method == "textDocument/didChange") {
    const json changes = params.value("contentChanges", json::array());
    for (const json& change : changes.is_array() ? changes : json::array()) {
      const std::optional<std::string> body = text(change, "text");
      if (!body) {
        continue;
      }
      const std::optional<Range> range = change.contains("range")
                                             ? rangeOfJson(change["range"])
                                             : std::nullopt;
      if (change.contains("range") && !range) {
        log(kLogWarning, fmt::format("a change of {} with a bad range", *uri));
        continue;
      }
      doc.text->apply(range, *body, encoding_);
    }
    doc.text->setVersion(
        integer(params["textDocument"], "version", doc.text->version()));
    doc.changed();
  } else if (method == "textDocument/didClose") {
    notify("textDocument/publishDiagnostics",
           {{"uri", *uri}, {"diagnostics", json::array()}});
    documents_.erase(it);
  }
}

json Server::initialize(const json& params) {
  // UTF-8 positions when the client takes them: no counting of UTF-16.
  const json encodings = params.is_object()
                             ? params.value("capabilities", json::object())
                                   .value("general", json::object())
                                   .value("positionEncodings", json::array())
                             : json::array();
  for (const json& e : encodings.is_array() ? encodings : json::array()) {
    if (e == "utf-8") {
      encoding_ = Encoding::Utf8;
    }
  }
  showDocument_ =
      params.is_object() && params.value("capabilities", json::object())
                                    .value("window", json::object())
                                    .value("showDocument", json::object())
                                    .value("support", false) == true;
  readWorkspaceSettings(params);
  initialized_ = true; // not before: parameters of the wrong type throw
  return {
      {"capabilities",
       {{"positionEncoding", encoding_ == Encoding::Utf8 ? "utf-8" : "utf-16"},
        {"textDocumentSync",
         {{"openClose", true}, {"change", kSyncIncremental}, {"save", true}}},
        {"hoverProvider", true},
        {"definitionProvider", true},
        {"documentSymbolProvider", true},
        {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}},
        {"referencesProvider", true},
        {"workspaceSymbolProvider", true},
        {"completionProvider", {{"triggerCharacters", {"#", "G", "M", "O"}}}},
        {"inlayHintProvider", true},
        {"semanticTokensProvider",
         {{"legend",
           {{"tokenTypes", kTokenTypes}, {"tokenModifiers", kTokenModifiers}}},
          {"full", true}}},
        {"codeLensProvider", {{"resolveProvider", true}}},
        {"executeCommandProvider", {{"commands", {kShowRunCommand}}}},
        {"signatureHelpProvider",
         {{"triggerCharacters",
           {"A", "B", "C", "D", "E", "F", "H", "I", "J", "K", "M",
            "Q", "R", "S", "T", "U", "V", "W", "X", "Y", "Z"}}}}}},
      {"serverInfo", {{"name", "mbc"}, {"version", MBC_VERSION_STRING}}}};
}

void Server::readWorkspaceSettings(const json& params) {
  if (!params.is_object()) {
    return;
  }
  std::optional<std::string> root;
  if (const std::optional<std::string> uri = text(params, "rootUri")) {
    root = pathOfUri(*uri);
  } else if (params.contains("workspaceFolders") &&
             params["workspaceFolders"].is_array() &&
             !params["workspaceFolders"].empty()) {
    if (const std::optional<std::string> folder =
            text(params["workspaceFolders"][0], "uri")) {
      root = pathOfUri(*folder);
    }
  }
  // The workspace's mbc.json, then the client's initialization options.
  json settings = json::object();
  if (root) {
    root_ = *root;
    std::ifstream file(std::filesystem::path(*root) / "mbc.json");
    if (file) {
      settings = json::parse(file, nullptr, false);
      if (!settings.is_object()) {
        log(kLogError, "mbc lsp: mbc.json of the workspace is not a JSON "
                       "object; it is left out");
        settings = json::object();
      }
    }
  }
  if (params.contains("initializationOptions") &&
      params["initializationOptions"].is_object()) {
    settings.update(params["initializationOptions"]);
  }
  const auto inRoot = [&](const std::string& path) {
    const std::filesystem::path p(path);
    return p.is_absolute() || root_.empty()
               ? p.string()
               : (std::filesystem::path(root_) / p).string();
  };
  if (settings.contains("include") && settings["include"].is_array()) {
    for (const json& dir : settings["include"]) {
      if (dir.is_string()) {
        userIncludes_.push_back(inRoot(dir.get<std::string>()));
      }
    }
  }
  if (const std::optional<std::string> machine = text(settings, "machine")) {
    useMachine(inRoot(*machine));
  }
  std::vector<std::string> folders = userIncludes_;
  if (!root_.empty()) {
    folders.insert(folders.begin(), root_);
  }
  index_.scan(folders);
}

void Server::useMachine(const std::string& path) {
  char err[512] = "";
  mbrt_ctx* ctx = mbrt_create_from_file(path.c_str(), err, sizeof err);
  if (ctx == nullptr) {
    log(kLogError, fmt::format("mbc lsp: the machine profile {}: {}; the "
                               "built-in machine is used",
                               path, err));
    return;
  }
  settings_.defaultMachine = false;
  settings_.machinePath = path;
  settings_.latheSystem = static_cast<char>(mbrt_lathe_system(ctx));
  mbrt_stats stats{};
  mbrt_get_stats(ctx, &stats);
  settings_.inch = std::string_view(stats.unit) == "inch";
  settings_.decimalPointInput =
      (static_cast<long>(mbrt_parameter(ctx, 3401)) & 1) != 0;
  mbrt_destroy(ctx);
}

AnalysisSettings Server::settingsFor(const TextDocument& doc) const {
  const std::optional<std::string> path = pathOfUri(doc.uri());
  AnalysisSettings settings = settings_;
  // Called programs are found beside the document, in the folders the
  // workspace names, and at its root.
  if (path) {
    settings.includeDirs.push_back(
        std::filesystem::path(*path).parent_path().string());
  }
  settings.includeDirs.insert(settings.includeDirs.end(), userIncludes_.begin(),
                              userIncludes_.end());
  if (!root_.empty()) {
    settings.includeDirs.push_back(root_);
  }
  return settings;
}

void Server::analyse(Document& doc) {
  if (!doc.analysis) {
    doc.analysis = lsp::analyse(nameOfUri(doc.text->uri()), doc.text->text(),
                                settingsFor(*doc.text), index_);
  }
}

void Server::fileChanged(const std::string& path) {
  index_.refresh(path);
  for (auto& [uri, doc] : documents_) {
    doc.changed();
  }
}

std::string Server::uriOf(std::uint32_t file, const Analysis& analysis,
                          const TextDocument& doc) const {
  if (file == 0) {
    return doc.uri();
  }
  std::error_code error;
  const std::filesystem::path absolute =
      std::filesystem::absolute(analysis.cu.sources.name(file), error);
  return uriOfPath(error ? analysis.cu.sources.name(file) : absolute.string());
}

json Server::rangeOf(const SourceRange& range, const Analysis& analysis,
                     const TextDocument& doc) const {
  const auto toRange = [&](const TextDocument& text) {
    return json{
        {"start", toJson(text.positionOf(range.begin.offset, encoding_))},
        {"end", toJson(text.positionOf(endOf(range), encoding_))}};
  };
  if (range.begin.file == 0) {
    return toRange(doc);
  }
  return toRange(TextDocument(
      "", 0, std::string(analysis.cu.sources.text(range.begin.file))));
}

void Server::publish(Document& doc) {
  analyse(doc);
  const Analysis& analysis = *doc.analysis;
  json diagnostics = json::array();
  for (std::size_t i = 0; i < analysis.diagnostics.size(); ++i) {
    const Diagnostic& d = analysis.diagnostics[i];
    if (d.range.begin.file != 0 && d.kind != DiagKind::TooManyErrors) {
      continue; // a called program's: its own document says it
    }
    const char* flag = warningFlag(d.kind);
    json one = {{"range", rangeOf(d.range, analysis, *doc.text)},
                {"severity", analysis.severities[i] == Severity::Error ? 1 : 2},
                {"code", flag != nullptr ? flag : kindName(d.kind)},
                {"source", "mbc"},
                {"message", d.message}};
    json related = json::array();
    for (const Diagnostic& note : d.notes) {
      related.push_back(
          {{"location",
            {{"uri", uriOf(note.range.begin.file, analysis, *doc.text)},
             {"range", rangeOf(note.range, analysis, *doc.text)}}},
           {"message", note.message}});
    }
    if (!related.empty()) {
      one["relatedInformation"] = related;
    }
    diagnostics.push_back(std::move(one));
  }
  if (!analysis.failure.empty()) {
    log(kLogWarning, "mbc lsp: " + analysis.failure);
  }
  notify("textDocument/publishDiagnostics", {{"uri", doc.text->uri()},
                                             {"version", doc.text->version()},
                                             {"diagnostics", diagnostics}});
  doc.published = true;
}

Server::Document* Server::document(const json& params) {
  const std::optional<std::string> uri = documentUri(params);
  const auto it = uri ? documents_.find(*uri) : documents_.end();
  if (it == documents_.end()) {
    return nullptr;
  }
  analyse(it->second);
  return &it->second;
}

std::optional<Server::Place> Server::placeOf(const json& params) {
  Document* doc = document(params);
  const std::optional<Position> at =
      positionOf(params.value("position", json()));
  if (doc == nullptr || !at) {
    return std::nullopt;
  }
  const auto offset =
      static_cast<std::uint32_t>(doc->text->offsetOf(*at, encoding_));
  return Place{doc, offset,
               findAt(doc->analysis->cu.unit, 0, doc->text->text(), offset)};
}

std::optional<json> Server::hover(const json& params) {
  const std::optional<Place> place = placeOf(params);
  if (!place) {
    return std::nullopt;
  }
  const Document& doc = *place->doc;
  const std::optional<Hover> hover =
      hoverAt(place->found, doc.analysis->cu.unit, doc.text->text(),
              settings_.latheSystem);
  if (!hover) {
    return json(nullptr);
  }
  return json{{"contents", {{"kind", "markdown"}, {"value", hover->markdown}}},
              {"range", rangeOf(hover->range, *doc.analysis, *doc.text)}};
}

std::optional<json> Server::definition(const json& params) {
  const std::optional<Place> at = placeOf(params);
  if (!at) {
    return std::nullopt;
  }
  Document* doc = at->doc;
  const Analysis& analysis = *doc->analysis;
  const Found& found = at->found;
  json out = json::array();
  for (const lsp::Place& place : definitionOf(found, analysis.cu)) {
    out.push_back({{"uri", uriOf(place.file, analysis, *doc->text)},
                   {"range", rangeOf(place.range, analysis, *doc->text)}});
  }
  // M99 P returns into the callers, which other open documents may hold.
  if (const std::optional<Return> r = returnAt(found)) {
    for (auto& [uri, other] : documents_) {
      if (&other == doc) {
        continue;
      }
      analyse(other);
      for (const lsp::Place& place :
           returnPlaces(other.analysis->cu.unit, *r)) {
        if (place.file == 0) {
          out.push_back(
              {{"uri", uri},
               {"range", rangeOf(place.range, *other.analysis, *other.text)}});
        }
      }
    }
  }
  return out;
}

std::optional<json> Server::documentSymbol(const json& params) {
  Document* doc = document(params);
  if (doc == nullptr) {
    return std::nullopt;
  }
  const Analysis& analysis = *doc->analysis;
  const std::function<json(const Symbol&)> toJsonSymbol = [&](const Symbol& s) {
    json children = json::array();
    for (const Symbol& child : s.children) {
      children.push_back(toJsonSymbol(child));
    }
    return json{{"name", s.name},
                {"detail", s.detail},
                {"kind", s.kind},
                {"range", rangeOf(s.range, analysis, *doc->text)},
                {"selectionRange", rangeOf(s.selection, analysis, *doc->text)},
                {"children", children}};
  };
  json out = json::array();
  for (const Symbol& s : documentSymbols(analysis.cu, 0)) {
    out.push_back(toJsonSymbol(s));
  }
  return out;
}

std::optional<Server::Span> Server::spanOf(const json& params) {
  Document* doc = document(params);
  const std::optional<Range> range = rangeOfJson(params.value("range", json()));
  if (doc == nullptr || !range) {
    return std::nullopt;
  }
  return Span{doc, *range};
}

std::optional<json> Server::codeAction(const json& params) {
  const std::optional<Span> span = spanOf(params);
  if (!span) {
    return std::nullopt;
  }
  Document* doc = span->doc;
  const Range* range = &span->range;
  const Analysis& analysis = *doc->analysis;
  // The lines asked about, whole: an editor asks at the cursor.
  const std::size_t begin =
      doc->text->offsetOf({range->start.line, 0}, encoding_);
  const std::size_t end =
      doc->text->offsetOf({range->end.line + 1, 0}, encoding_);
  json out = json::array();
  // Each fix-it of a diagnostic there, as a quick fix that edits the
  // document as the fix-it says.
  for (const Diagnostic& d : analysis.diagnostics) {
    if (d.range.begin.file != 0 || d.fixIts.empty() || endOf(d.range) < begin ||
        d.range.begin.offset > end) {
      continue;
    }
    json edits = json::array();
    std::string title;
    for (const FixIt& fix : d.fixIts) {
      edits.push_back({{"range", rangeOf(fix.range, analysis, *doc->text)},
                       {"newText", fix.replacement}});
      const std::string_view replaced =
          std::string_view(doc->text->text())
              .substr(fix.range.begin.offset, fix.range.length);
      title =
          fix.range.length == 0 ? fmt::format("Insert '{}'", fix.replacement)
          : fix.replacement.empty() ? fmt::format("Remove '{}'", replaced)
                                    : fmt::format("Replace '{}' with '{}'",
                                                  replaced, fix.replacement);
    }
    const char* flag = warningFlag(d.kind);
    out.push_back(
        {{"title", d.fixIts.size() == 1 ? title : "Apply mbc's fix-its"},
         {"kind", "quickfix"},
         {"isPreferred", true},
         {"diagnostics",
          json::array({{{"range", rangeOf(d.range, analysis, *doc->text)},
                        {"message", d.message},
                        {"source", "mbc"},
                        {"code", flag != nullptr ? flag : kindName(d.kind)}}})},
         {"edit", {{"changes", {{doc->text->uri(), edits}}}}}});
  }
  return out;
}

std::optional<json> Server::references(const json& params) {
  const std::optional<Place> at = placeOf(params);
  if (!at) {
    return std::nullopt;
  }
  const json context = params.value("context", json::object());
  const bool declaration = context.is_object() &&
                           context.value("includeDeclaration", json()) == true;
  const Analysis& analysis = *at->doc->analysis;
  json out = json::array();
  std::set<std::pair<std::string, json>> said;
  const auto add = [&](const std::string& uri, json range) {
    if (said.emplace(uri, range).second) {
      out.push_back({{"uri", uri}, {"range", std::move(range)}});
    }
  };
  for (const lsp::Place& place :
       referencesOf(at->found, analysis.cu.unit, declaration)) {
    add(uriOf(place.file, analysis, *at->doc->text),
        rangeOf(place.range, analysis, *at->doc->text));
  }
  // A common variable or a program is named in other documents too.
  const SharedName name = sharedNameOf(at->found);
  if (name.variable >= 0 || name.program >= 0) {
    for (auto& [uri, other] : documents_) {
      if (&other == at->doc) {
        continue;
      }
      analyse(other);
      for (const lsp::Place& place :
           placesOf(name, other.analysis->cu.unit, 0, declaration)) {
        add(uri, rangeOf(place.range, *other.analysis, *other.text));
      }
    }
  }
  return out;
}

std::optional<json> Server::completion(const json& params) {
  const std::optional<Place> at = placeOf(params);
  if (!at) {
    return std::nullopt;
  }
  const Document& doc = *at->doc;
  json items = json::array();
  for (const Completion& c :
       completionsAt(doc.text->text(), at->offset, at->found.program,
                     settings_.latheSystem)) {
    items.push_back({{"label", c.label},
                     {"kind", c.kind},
                     {"detail", c.detail},
                     {"textEdit",
                      {{"range", rangeOf(c.replaced, *doc.analysis, *doc.text)},
                       {"newText", c.label}}}});
  }
  return json{{"isIncomplete", false}, {"items", items}};
}

std::optional<json> Server::workspaceSymbol(const json& params) {
  constexpr std::size_t kMaxSymbols = 500;
  constexpr int kFunctionSymbol = 12;
  const std::string query =
      params.is_object() ? params.value("query", "") : std::string();
  json out = json::array();
  for (const ProgramIndex::Entry& e : index_.matching(query, kMaxSymbols)) {
    const Position start{e.line, 0};
    const Position end{e.line, static_cast<int>(e.program.name.size())};
    out.push_back(
        {{"name", e.program.name},
         {"kind", kFunctionSymbol},
         {"location",
          {{"uri", uriOfPath(e.path)},
           {"range", {{"start", toJson(start)}, {"end", toJson(end)}}}}}});
  }
  return out;
}

std::optional<json> Server::inlayHint(const json& params) {
  const std::optional<Span> span = spanOf(params);
  if (!span) {
    return std::nullopt;
  }
  Document* doc = span->doc;
  const Range* range = &span->range;
  const auto begin =
      static_cast<std::uint32_t>(doc->text->offsetOf(range->start, encoding_));
  const auto end =
      static_cast<std::uint32_t>(doc->text->offsetOf(range->end, encoding_));
  json out = json::array();
  for (const ArgumentHint& hint :
       argumentHints(doc->analysis->cu.unit, 0, begin, end)) {
    out.push_back(
        {{"position", toJson(doc->text->positionOf(hint.offset, encoding_))},
         {"label", std::string(1, hint.letter)},
         {"kind", 2}, // a parameter's
         {"paddingLeft", true},
         {"tooltip", fmt::format("argument {} of G65/G66", hint.letter)}});
  }
  return out;
}

std::optional<json> Server::signatureHelp(const json& params) {
  const std::optional<Place> at = placeOf(params);
  if (!at) {
    return std::nullopt;
  }
  const std::optional<Signature> sig = signatureAt(
      at->found, at->doc->analysis->cu.unit, at->doc->text->text(), at->offset);
  if (!sig) {
    return json(nullptr);
  }
  json parameters = json::array();
  for (const std::string& letter : sig->letters) {
    parameters.push_back({{"label", letter}});
  }
  json signature = {{"label", sig->label},
                    {"documentation",
                     "the argument letters the macro reads (specification I)"},
                    {"parameters", parameters}};
  if (sig->active >= 0) {
    signature["activeParameter"] = sig->active;
  }
  return json{{"signatures", json::array({signature})}, {"activeSignature", 0}};
}

std::optional<json> Server::semanticTokens(const json& params) {
  Document* doc = document(params);
  if (doc == nullptr) {
    return std::nullopt;
  }
  // Each token as five numbers: its line and start relative to the last
  // token's, its length, type and modifiers.
  std::vector<int> data;
  Position last;
  for (const SemanticToken& t :
       lsp::semanticTokens(doc->analysis->cu.sources, 0)) {
    const Position start = doc->text->positionOf(t.offset, encoding_);
    const Position end = doc->text->positionOf(t.offset + t.length, encoding_);
    if (end.line != start.line) {
      continue; // the protocol's tokens hold one line
    }
    data.insert(data.end(),
                {start.line - last.line,
                 start.line == last.line ? start.character - last.character
                                         : start.character,
                 end.character - start.character, t.type, t.modifiers});
    last = start;
  }
  return json{{"data", data}};
}

int runServer(int in, std::FILE* out) {
  // The reader runs ahead on its own thread, so that a batch holds every
  // message that arrived while the last one was served; messages that
  // arrive together are handed over together, so that a request and its
  // cancel written at once are never served apart. It may still wait for
  // input when the server exits: it owns the queue with it.
  struct Queue {
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<Incoming> items;
    bool ended = false;
  };

  const auto queue = std::make_shared<Queue>();
  std::thread([queue, in] {
    FdSource source(in);
    MessageReader messages(source);
    std::deque<Incoming> arrived;
    for (;;) {
      Incoming next = messages.next();
      const bool ended = next.kind == Incoming::Kind::End;
      if (!ended) {
        arrived.push_back(std::move(next));
        if (source.ready() && arrived.size() < kMessagesHeldAtMost) {
          continue;
        }
      }
      const std::lock_guard lock(queue->mutex);
      std::move(arrived.begin(), arrived.end(),
                std::back_inserter(queue->items));
      arrived.clear();
      queue->ended = ended;
      queue->ready.notify_one();
      if (ended) {
        return;
      }
    }
  }).detach();
  Server server([out](const std::string& body) { writeMessage(out, body); });
  while (!server.exited()) {
    std::deque<Incoming> batch;
    {
      std::unique_lock lock(queue->mutex);
      queue->ready.wait(lock,
                        [&] { return queue->ended || !queue->items.empty(); });
      if (queue->items.empty()) {
        break; // the input ended without exit
      }
      batch.swap(queue->items);
    }
    std::vector<std::string> bodies;
    for (Incoming& item : batch) {
      if (item.kind == Incoming::Kind::Problem) {
        server.problem(item.problem);
      } else {
        bodies.push_back(std::move(item.body));
      }
    }
    server.handleBatch(bodies);
  }
  return server.exitCode();
}

} // namespace mbc::lsp
