// Where the programs of a workspace are: every O number and <NAME> that
// starts a line of a file under the workspace's folders, so that a call
// finds its program in a library file of many programs, where the program
// search path (toolchain/program_search.h) finds files named for one.
#pragma once

#include "frontend/called_programs.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mbc::lsp {

class ProgramIndex {
public:
  /// Reads the folders and those under them (not hidden ones, nor build
  /// and node_modules), at most kMaxFiles files of at most kMaxFileBytes.
  void scan(const std::vector<std::string>& dirs);

  /// Reads a file again after it changed (or was made or removed).
  void refresh(const std::string& path);

  /// The file that defines a program, if the index has one.
  std::optional<std::string> fileOf(const CalledProgram& program) const;

  struct Entry {
    CalledProgram program;
    std::string path;
    int line; // 0-based
  };

  /// The programs whose name holds `query` (any case), at most `limit`.
  std::vector<Entry> matching(std::string_view query, std::size_t limit) const;

  static constexpr std::size_t kMaxFiles = 20000;
  static constexpr std::size_t kMaxFileBytes = 16u << 20;

private:
  void scanFile(const std::string& path);

  std::map<CalledProgram, std::pair<std::string, int>> files_;
  std::size_t scanned_ = 0;
};

} // namespace mbc::lsp
