// Macro arguments (see arguments.h).
#include "lsp/arguments.h"

#include "frontend/called_programs.h"
#include <mbc/addresses.h>

#include <algorithm>
#include <set>

#include "lsp/navigation.h"

namespace mbc::lsp {

namespace {

/// Every read of a variable in a program.
template <typename Visit> void eachRead(const Program& p, Visit visit) {
  for (const Block& b : p.blocks) {
    eachExpr(b.stmt, [&](const Expr& e) {
      if (e.kind == ExprKind::Var) {
        visit(e);
      }
    });
  }
}

} // namespace

std::vector<ArgumentHint> argumentHints(const Unit& unit, std::uint32_t file,
                                        std::uint32_t begin,
                                        std::uint32_t end) {
  std::vector<ArgumentHint> out;
  const std::vector<bool> main = mainPrograms(unit);
  for (std::size_t i = 0; i < unit.programs.size(); ++i) {
    const Program& p = unit.programs[i];
    if (p.file != file || main[i]) {
      continue;
    }
    eachRead(p, [&](const Expr& e) {
      const std::uint32_t after = endOf(e.range);
      const char letter = argumentLetter(e.var);
      if (letter != 0 && after >= begin && after <= end) {
        out.push_back({after, letter});
      }
    });
  }
  return out;
}

std::optional<Signature> signatureAt(const Found& found, const Unit& unit,
                                     std::string_view text,
                                     std::uint32_t offset) {
  if (found.block == nullptr) {
    return std::nullopt;
  }
  const Stmt& s = found.block->stmt;
  const std::optional<int> number = calledNumber(s);
  // G65, or G66/G66.1 (an M98 passes no arguments).
  const bool modal =
      std::any_of(s.words.begin(), s.words.end(), [](const Word& w) {
        return w.letter == 'G' && w.value &&
               w.value->kind == ExprKind::Number &&
               (w.value->number == 66 || w.value->number == 66.1);
      });
  if (!number || (s.kind != StmtKind::MacroCall && !modal)) {
    return std::nullopt;
  }
  const std::vector<const Word*> args = callArguments(s);
  const Program* callee = nullptr;
  for (const Program& p : unit.programs) {
    if (p.number == *number && !p.duplicate) {
      callee = &p;
      break;
    }
  }
  if (callee == nullptr) {
    return std::nullopt;
  }
  std::set<char> read;
  eachRead(*callee, [&](const Expr& e) {
    if (const char letter = argumentLetter(e.var)) {
      read.insert(letter);
    }
  });
  // The program's line as its header writes it ("O9040(CORNER)") when it
  // is in this document, else its name.
  Signature sig;
  sig.label = callee->name;
  if (callee->range.begin.file == found.block->range.begin.file) {
    const std::size_t begin = callee->range.begin.offset;
    const std::size_t lineEnd =
        std::min(text.find_first_of("\r\n", begin), text.size());
    sig.label = std::string(text.substr(begin, lineEnd - begin));
  }
  char current = 0;
  for (const Word* w : args) {
    if (w->range.begin.offset <= offset) {
      current = w->letter;
    }
  }
  for (const char letter : read) {
    if (letter == current) {
      sig.active = static_cast<int>(sig.letters.size());
    }
    sig.letters.emplace_back(1, letter);
    sig.label += ' ';
    sig.label += letter;
  }
  return sig;
}

} // namespace mbc::lsp
