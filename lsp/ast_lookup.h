// What is written at a place of a document: the program, block, word and
// innermost expression whose source range holds a byte offset, for hover
// and go to definition.
#pragma once

#include "frontend/ast.h"

#include <cstdint>
#include <string_view>

namespace mbc::lsp {

struct Found {
  const Program* program = nullptr;
  const Block* block = nullptr;
  const Word* word = nullptr; // the address word, if the place is in one
  const Expr* expr = nullptr; // the innermost expression
  bool onSequence = false;    // on the block's own N number
};

/// `text` is the file's text (to find a block's N, which the AST keeps as
/// a number only).
Found findAt(const Unit& unit, std::uint32_t file, std::string_view text,
             std::uint32_t offset);

/// The end (exclusive) of a source range.
inline std::uint32_t endOf(const SourceRange& r) {
  return r.begin.offset + r.length;
}

inline bool holds(const SourceRange& r, std::uint32_t file,
                  std::uint32_t offset) {
  return r.begin.file == file && offset >= r.begin.offset && offset <= endOf(r);
}

/// The range of a block's N word ("N100"), or a zero length range.
SourceRange sequenceRange(const Block& block, std::string_view text);

} // namespace mbc::lsp
