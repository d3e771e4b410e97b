// Line tables for source files: every diagnostic and alarm location goes
// through here.
#include "frontend/source.h"

#include <algorithm>

namespace mbc {

std::uint32_t SourceManager::add(std::string name, std::string text) {
  File f{std::move(name), std::move(text), {0}};
  // A lone CR ends a line too (old Mac files): the control ignores CR, but
  // diagnostics must still point at the physical line.
  for (std::uint32_t i = 0; i < f.text.size(); ++i) {
    char c = f.text[i];
    if (c == '\n' ||
        (c == '\r' && (i + 1 >= f.text.size() || f.text[i + 1] != '\n'))) {
      f.lineStarts.push_back(i + 1);
    }
  }
  files_.push_back(std::move(f));
  return static_cast<std::uint32_t>(files_.size() - 1);
}

LineCol SourceManager::lineCol(SourceLoc loc) const {
  const auto& starts = files_[loc.file].lineStarts;
  auto it = std::upper_bound(starts.begin(), starts.end(), loc.offset);
  auto line = static_cast<int>(it - starts.begin());
  return {line, static_cast<int>(loc.offset - starts[line - 1]) + 1};
}

std::string_view SourceManager::lineText(SourceLoc loc) const {
  const File& f = files_[loc.file];
  int line = lineCol(loc).line;
  std::uint32_t begin = f.lineStarts[line - 1];
  std::uint32_t end = begin;
  while (end < f.text.size() && f.text[end] != '\n' && f.text[end] != '\r') {
    ++end;
  }
  return std::string_view(f.text).substr(begin, end - begin);
}

} // namespace mbc
