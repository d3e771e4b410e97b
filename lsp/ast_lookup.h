// What is written at a place of a document: the program, block, word and
// innermost expression whose source range holds a byte offset, for hover
// and go to definition.
#pragma once

#include "frontend/ast.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace mbc::lsp {

struct Found {
  const Program* program = nullptr;
  const Block* block = nullptr;
  const Word* word = nullptr; // the address word, if the place is in one
  const Expr* expr = nullptr; // the innermost expression
  bool onSequence = false;    // on the block's own N number
  bool onTarget = false;      // on the #n an assignment writes
};

/// The variable read or written at the place: #n, or none.
struct VariableAt {
  int number;
  SourceRange range;
};

std::optional<VariableAt> variableAt(const Found& found);

/// `text` is the file's text (to find a block's N, which the AST keeps as
/// a number only).
Found findAt(const Unit& unit, std::uint32_t file, std::string_view text,
             std::uint32_t offset);

/// The value of an expression written as a number, or none.
inline std::optional<double> constantOf(const Expr* e) {
  if (e != nullptr && e->kind == ExprKind::Number) {
    return e->number;
  }
  return std::nullopt;
}

/// The end (exclusive) of a source range.
inline std::uint32_t endOf(const SourceRange& r) {
  return r.begin.offset + r.length;
}

inline bool holds(const SourceRange& r, std::uint32_t file,
                  std::uint32_t offset) {
  return r.begin.file == file && offset >= r.begin.offset && offset <= endOf(r);
}

/// Calls `visit` on every expression of a statement, inner ones too.
template <typename Visit> void eachExpr(const Expr* e, Visit& visit) {
  if (e == nullptr) {
    return;
  }
  visit(*e);
  for (const ExprPtr& arg : e->args) {
    eachExpr(arg.get(), visit);
  }
}

template <typename Visit> void eachExpr(const Stmt& s, Visit visit) {
  for (const std::vector<Word>* words : {&s.words, &s.leadCodes}) {
    for (const Word& w : *words) {
      eachExpr(w.value.get(), visit);
    }
  }
  for (const Expr* e : {s.target.index.get(), s.value.get(), s.cond.get(),
                        s.program.get(), s.repeat.get()}) {
    eachExpr(e, visit);
  }
  for (const PrintItem& item : s.items) {
    eachExpr(item.value.get(), visit);
  }
}

/// The range of a block's N word ("N100"), or a zero length range.
SourceRange sequenceRange(const Block& block, std::string_view text);

} // namespace mbc::lsp
