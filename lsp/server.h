// `mbc lsp`: a Language Server Protocol (3.17) server over the input and
// output it is given. The server takes the client's messages in batches
// (all that have arrived): a request a later message of the batch cancels,
// or whose document a later change makes stale, is answered as such
// rather than computed; the documents changed are analysed once per batch
// and their diagnostics published.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lsp/analysis.h"
#include "lsp/ast_lookup.h"
#include "lsp/program_index.h"
#include "lsp/program_runs.h"
#include "lsp/text_document.h"

namespace mbc::lsp {

class Server {
public:
  using Send = std::function<void(const std::string&)>;

  /// `runBlocks`: the budget of a lens's run (a fuzzer's is smaller).
  explicit Server(Send send, std::uint64_t runBlocks = kRunBlockBudget)
      : send_(std::move(send)), runBlocks_(runBlocks) {}

  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// The messages that arrived together, in order.
  void handleBatch(const std::vector<std::string>& bodies);

  /// A message the input could not frame: said in the client's log.
  void problem(const std::string& what);

  bool exited() const { return exited_; }

  /// 0 when the client asked to shut down before it said exit.
  int exitCode() const { return shutdown_ ? 0 : 1; }

private:
  struct Document {
    std::unique_ptr<TextDocument> text;
    std::unique_ptr<Analysis> analysis;     // null until analysed again
    std::map<std::string, RunSummary> runs; // the lenses', by program
    bool published = false;

    /// The text, or what it calls, changed: everything known is stale.
    void changed() {
      analysis.reset();
      runs.clear();
      published = false;
    }
  };

  void dispatch(const nlohmann::json& message, bool stale, bool cancelled);
  void request(const nlohmann::json& id, const std::string& method,
               const nlohmann::json& params);
  void notification(const std::string& method, const nlohmann::json& params);

  nlohmann::json initialize(const nlohmann::json& params);
  void readWorkspaceSettings(const nlohmann::json& params);
  void useMachine(const std::string& path);

  std::optional<nlohmann::json> hover(const nlohmann::json& params);
  std::optional<nlohmann::json> definition(const nlohmann::json& params);
  std::optional<nlohmann::json> documentSymbol(const nlohmann::json& params);
  std::optional<nlohmann::json> codeAction(const nlohmann::json& params);
  std::optional<nlohmann::json> references(const nlohmann::json& params);
  std::optional<nlohmann::json> completion(const nlohmann::json& params);
  std::optional<nlohmann::json> workspaceSymbol(const nlohmann::json& params);
  std::optional<nlohmann::json> inlayHint(const nlohmann::json& params);
  std::optional<nlohmann::json> signatureHelp(const nlohmann::json& params);
  std::optional<nlohmann::json> semanticTokens(const nlohmann::json& params);
  // The code lenses (server_lenses.cpp).
  std::optional<nlohmann::json> codeLens(const nlohmann::json& params);
  std::optional<nlohmann::json> codeLensResolve(const nlohmann::json& params);
  std::optional<nlohmann::json> executeCommand(const nlohmann::json& params);
  /// The lens's document when it is still the text the lens was made for.
  Document* lensDocument(const nlohmann::json& lens);
  /// A run of a program of an open document, the run's view with `html`.
  RunSummary run(Document& doc, const std::string& program,
                 const std::string& html);
  /// Where the views of runs are written: a folder of this session's.
  std::string viewFolder();

  /// The open document a request names, analysed; nullptr if none.
  Document* document(const nlohmann::json& params);

  /// What a request at a place (textDocument and position) is about.
  struct Place {
    Document* doc;
    std::uint32_t offset;
    Found found;
  };

  std::optional<Place> placeOf(const nlohmann::json& params);

  /// What a request over a span (textDocument and range) is about.
  struct Span {
    Document* doc;
    Range range;
  };

  std::optional<Span> spanOf(const nlohmann::json& params);
  /// How a document is read: the workspace's settings, with its folder.
  AnalysisSettings settingsFor(const TextDocument& doc) const;
  void analyse(Document& doc);
  /// A file of the workspace changed: the index reads it again, and every
  /// open document is read again (what it calls may have changed).
  void fileChanged(const std::string& path);
  void publish(Document& doc);

  nlohmann::json rangeOf(const SourceRange& range, const Analysis& analysis,
                         const TextDocument& doc) const;
  std::string uriOf(std::uint32_t file, const Analysis& analysis,
                    const TextDocument& doc) const;

  void respond(const nlohmann::json& id, nlohmann::json result);
  /// A request of the server's own; the client's answer is not awaited.
  void ask(const std::string& method, nlohmann::json params);
  void fail(const nlohmann::json& id, int code, const std::string& message);
  void notify(const std::string& method, nlohmann::json params);
  void log(int type, const std::string& message);

  Send send_;
  std::uint64_t runBlocks_;
  bool initialized_ = false;
  bool shutdown_ = false;
  bool exited_ = false;
  Encoding encoding_ = Encoding::Utf16;
  bool showDocument_ = false; // the client opens a URI it is sent
  int asked_ = 0;             // the server's own requests so far
  std::string viewFolder_;
  std::string root_;
  AnalysisSettings settings_;
  std::vector<std::string> userIncludes_;
  ProgramIndex index_;
  std::map<std::string, Document> documents_;
};

/// Serves the file descriptor `in` and the stream `out` until the client
/// says exit or the input ends;
/// the exit status.
int runServer(int in, std::FILE* out);

} // namespace mbc::lsp
