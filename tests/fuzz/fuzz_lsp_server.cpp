// libFuzzer target: the language server's handling of what an editor
// sends, past the framing (fuzz_lsp): each line of the input is a
// message's JSON, and an empty line ends a batch, as messages that arrive
// together are served. Nothing the messages say may crash the server or
// make it hang: members of any type, positions anywhere, documents of any
// text, lenses and commands of documents that changed. The workspace is
// an empty folder of the target's own, whatever initialize names, so that
// no input has the index read the machine's files.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/server.h"
#include "lsp/uri.h"

namespace {

constexpr std::uint64_t kRunBlocks = 20000;

/// The workspace every session gets.
const std::string& emptyRoot() {
  static const std::string root = [] {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "mbc-fuzz-lsp-XXXXXX")
            .string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::abort();
    }
    return mbc::lsp::uriOfPath(pattern);
  }();
  return root;
}

/// An initialize's folders and include folders replaced by the empty one.
std::string confined(std::string_view line) {
  nlohmann::json message = nlohmann::json::parse(line, nullptr, false);
  if (!message.is_object() ||
      message.value("method", nlohmann::json()) != "initialize" ||
      !message.contains("params") || !message["params"].is_object()) {
    return std::string(line);
  }
  nlohmann::json& params = message["params"];
  params["rootUri"] = emptyRoot();
  params.erase("rootPath");
  params.erase("workspaceFolders");
  if (params.contains("initializationOptions") &&
      params["initializationOptions"].is_object()) {
    params["initializationOptions"].erase("include");
  }
  return message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  std::string_view input(reinterpret_cast<const char*>(data), size);
  // A lens's run stops after a budget a sanitized build runs in well
  // under the fuzzer's timeout.
  mbc::lsp::Server server([](const std::string&) {}, kRunBlocks);
  std::vector<std::string> batch;
  while (!input.empty() && !server.exited()) {
    const std::size_t end = std::min(input.find('\n'), input.size());
    const std::string_view line = input.substr(0, end);
    input.remove_prefix(std::min(end + 1, input.size()));
    if (line.empty()) {
      server.handleBatch(batch);
      batch.clear();
    } else {
      batch.push_back(confined(line));
    }
  }
  if (!batch.empty() && !server.exited()) {
    server.handleBatch(batch);
  }
  return 0;
}
