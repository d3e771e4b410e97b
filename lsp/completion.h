// Completion: what may be written where the cursor is, from mbc's tables
// (G codes, the system variable map, the functions) and the program (the
// N labels a GOTO may name).
#pragma once

#include "frontend/ast.h"

#include <string>
#include <string_view>
#include <vector>

namespace mbc::lsp {

struct Completion {
  std::string label;
  int kind; // the protocol's CompletionItemKind
  std::string detail;
  SourceRange replaced; // what the item replaces: the word begun
};

/// `text`: the document; `program`: the program the cursor is in, or
/// nullptr; `latheSystem`: the profile's, 0 on a mill.
std::vector<Completion> completionsAt(std::string_view text,
                                      std::uint32_t offset,
                                      const Program* program, char latheSystem);

} // namespace mbc::lsp
