// Finding what is written at a place (see ast_lookup.h).
#include "lsp/ast_lookup.h"

#include <cctype>

namespace mbc::lsp {

namespace {

/// The innermost expression of `e` that holds the offset, or nullptr.
const Expr* innermost(const Expr* e, std::uint32_t file, std::uint32_t offset) {
  if (e == nullptr || !holds(e->range, file, offset)) {
    return nullptr;
  }
  for (const ExprPtr& arg : e->args) {
    if (const Expr* inner = innermost(arg.get(), file, offset)) {
      return inner;
    }
  }
  return e;
}

void lookIn(const std::vector<Word>& words, std::uint32_t file,
            std::uint32_t offset, Found& found) {
  for (const Word& w : words) {
    if (holds(w.range, file, offset)) {
      found.word = &w;
      found.expr = innermost(w.value.get(), file, offset);
      return;
    }
  }
}

void lookIn(const Stmt& s, std::uint32_t file, std::uint32_t offset,
            Found& found) {
  lookIn(s.words, file, offset, found);
  lookIn(s.leadCodes, file, offset, found);
  if (found.word != nullptr) {
    return;
  }
  if ((s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen) &&
      !s.target.index && holds(s.target.range, file, offset)) {
    found.onTarget = true;
    return;
  }
  for (const Expr* e : {s.target.index.get(), s.value.get(), s.cond.get(),
                        s.program.get(), s.repeat.get()}) {
    if (const Expr* inner = innermost(e, file, offset)) {
      found.expr = inner;
      return;
    }
  }
  for (const PrintItem& item : s.items) {
    if (const Expr* inner = innermost(item.value.get(), file, offset)) {
      found.expr = inner;
      return;
    }
  }
}

} // namespace

std::optional<VariableAt> variableAt(const Found& found) {
  if (found.onTarget) {
    const VarTarget& t = found.block->stmt.target;
    return VariableAt{t.number, t.range};
  }
  if (found.expr != nullptr && found.expr->kind == ExprKind::Var) {
    return VariableAt{found.expr->var, found.expr->range};
  }
  return std::nullopt;
}

SourceRange sequenceRange(const Block& block, std::string_view text) {
  SourceRange r{block.range.begin, 0};
  if (block.seq < 0) {
    return r;
  }
  std::uint32_t at = block.range.begin.offset;
  const auto end = std::min<std::size_t>(endOf(block.range), text.size());
  // A block skip ("/", "/2") may come first.
  while (at < end && (text[at] == '/' || text[at] == ' ' ||
                      std::isdigit(static_cast<unsigned char>(text[at])))) {
    ++at;
  }
  if (at < end && (text[at] == 'N' || text[at] == 'n')) {
    std::uint32_t stop = at + 1;
    while (stop < end && std::isdigit(static_cast<unsigned char>(text[stop]))) {
      ++stop;
    }
    r.begin.offset = at;
    r.length = stop - at;
  }
  return r;
}

Found findAt(const Unit& unit, std::uint32_t file, std::string_view text,
             std::uint32_t offset) {
  Found found;
  for (const Program& p : unit.programs) {
    if (p.file != file) {
      continue;
    }
    for (const Block& b : p.blocks) {
      if (!holds(b.range, file, offset)) {
        continue;
      }
      found.program = &p;
      found.block = &b;
      const SourceRange n = sequenceRange(b, text);
      if (n.length > 0 && holds(n, file, offset)) {
        found.onSequence = true;
        return found;
      }
      lookIn(b.stmt, file, offset, found);
      return found;
    }
    if (holds(p.range, file, offset)) {
      found.program = &p;
    }
  }
  return found;
}

} // namespace mbc::lsp
