// Source files and locations. A location is a file id and a byte offset; the
// manager turns it into line, column and the text of the line for carets.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mbc {

struct SourceLoc {
  std::uint32_t file = 0;
  std::uint32_t offset = 0;
};

struct SourceRange {
  SourceLoc begin;
  std::uint32_t length = 0;
};

struct LineCol {
  int line = 0; // 1-based
  int col = 0;  // 1-based, in bytes
};

class SourceManager {
public:
  /// Adds a file's text; returns its id.
  std::uint32_t add(std::string name, std::string text);

  std::uint32_t fileCount() const {
    return static_cast<std::uint32_t>(files_.size());
  }

  const std::string& name(std::uint32_t file) const {
    return files_[file].name;
  }

  std::string_view text(std::uint32_t file) const { return files_[file].text; }

  LineCol lineCol(SourceLoc loc) const;
  /// The physical line holding loc, without its end-of-line characters.
  std::string_view lineText(SourceLoc loc) const;

private:
  struct File {
    std::string name;
    std::string text;
    std::vector<std::uint32_t> lineStarts;
  };

  std::vector<File> files_;
};

} // namespace mbc
