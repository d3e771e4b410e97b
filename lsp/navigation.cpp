// Definitions and symbols (see navigation.h).
#include "lsp/navigation.h"

#include "frontend/called_programs.h"
#include <mbc/addresses.h>
#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/limits.h>

#include <fmt/format.h>

#include <optional>
#include <set>

namespace mbc::lsp {

namespace {

constexpr int kFunctionSymbol = 12;
constexpr int kKeySymbol = 20;
constexpr int kNamespaceSymbol = 3;

const Word* wordOf(const Stmt& s, char letter) {
  for (const Word& w : s.words) {
    if (w.letter == letter) {
      return &w;
    }
  }
  return nullptr;
}

bool hasCode(const Stmt& s, char letter, double code) {
  for (const Word& w : s.words) {
    if (w.letter == letter && constantOf(w.value.get()) == code) {
      return true;
    }
  }
  return false;
}

SourceRange wholeProgram(const Program& p) {
  SourceRange r = p.range;
  if (!p.blocks.empty()) {
    const SourceRange& last = p.blocks.back().range;
    r.length = std::max(r.length, endOf(last) - r.begin.offset);
  }
  return r;
}

Place placeOf(const SourceRange& r) {
  return {r.begin.file, r};
}

} // namespace

std::optional<int> calledNumber(const Stmt& s) {
  if (s.kind == StmtKind::MacroCall) {
    if (const std::optional<double> p = constantOf(s.program.get())) {
      return calledProgramNumber(*p);
    }
    return std::nullopt;
  }
  bool calls = false;
  for (const Word& w : s.words) {
    if (const std::optional<double> v = constantOf(w.value.get())) {
      calls = calls || callsByP(w.letter, *v);
    }
  }
  const Word* p = wordOf(s, 'P');
  if (!calls || p == nullptr) {
    return std::nullopt;
  }
  if (const std::optional<double> v = constantOf(p->value.get())) {
    return calledProgramNumber(*v);
  }
  return std::nullopt;
}

std::vector<Place> definitionOf(const Found& found,
                                const toolchain::CompiledUnit& cu) {
  std::vector<Place> out;
  if (found.block == nullptr || variableAt(found)) {
    return out;
  }
  const Stmt& s = found.block->stmt;
  if (s.gotoBlock) {
    const Block& target =
        found.program->blocks[static_cast<std::size_t>(*s.gotoBlock)];
    out.push_back(placeOf(target.range));
    return out;
  }
  if (const std::optional<int> number = calledNumber(s)) {
    for (const Program& p : cu.unit.programs) {
      if (p.number == *number && !p.duplicate) {
        out.push_back(placeOf(p.range));
      }
    }
    return out;
  }
  if (const std::optional<Return> r = returnAt(found)) {
    out = returnPlaces(cu.unit, *r);
  }
  return out;
}

std::optional<Return> returnAt(const Found& found) {
  if (found.block == nullptr) {
    return std::nullopt;
  }
  const Stmt& s = found.block->stmt;
  const Word* p = wordOf(s, 'P');
  if (s.kind != StmtKind::Nc || !hasCode(s, 'M', 99) || p == nullptr) {
    return std::nullopt;
  }
  const std::optional<double> n = constantOf(p->value.get());
  if (!n) {
    return std::nullopt;
  }
  return Return{found.program->number, static_cast<int>(*n)};
}

std::vector<Place> returnPlaces(const Unit& unit, const Return& r) {
  std::vector<Place> out;
  for (const Program& caller : unit.programs) {
    bool calls = caller.number == r.callee;
    for (const Block& b : caller.blocks) {
      calls = calls || calledNumber(b.stmt) == r.callee;
    }
    for (const Block& b : caller.blocks) {
      if (calls && b.seq == r.seq) {
        out.push_back(placeOf(b.range));
      }
    }
  }
  return out;
}

namespace {

/// Reads and writes of #n in a program.
void variablePlaces(const Program& p, int n, std::vector<Place>& out) {
  for (const Block& b : p.blocks) {
    const Stmt& s = b.stmt;
    if ((s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen) &&
        !s.target.index && s.target.number == n) {
      out.push_back(placeOf(s.target.range));
    }
    eachExpr(s, [&](const Expr& e) {
      if (e.kind == ExprKind::Var && e.var == n) {
        out.push_back(placeOf(e.range));
      }
    });
  }
}

} // namespace

SharedName sharedNameOf(const Found& found) {
  if (const std::optional<VariableAt> v = variableAt(found);
      v && !isLocal(v->number)) {
    return {v->number, -1};
  }
  if (found.block != nullptr) {
    if (const std::optional<int> n = calledNumber(found.block->stmt)) {
      return {-1, *n};
    }
  }
  if (found.block == nullptr && found.program != nullptr &&
      found.program->number >= 0) {
    return {-1, found.program->number}; // on the O line
  }
  return {};
}

std::vector<Place> placesOf(const SharedName& name, const Unit& unit,
                            std::uint32_t file, bool declaration) {
  std::vector<Place> out;
  for (const Program& p : unit.programs) {
    if (p.file != file) {
      continue;
    }
    if (name.variable >= 0) {
      variablePlaces(p, name.variable, out);
      continue;
    }
    if (declaration && p.number == name.program && !p.duplicate) {
      out.push_back(placeOf(p.range));
    }
    for (const Block& b : p.blocks) {
      if (calledNumber(b.stmt) == name.program) {
        const std::optional<ProgramCall> call = programCallOf(b.stmt);
        out.push_back(placeOf(call ? call->range : b.range));
      }
    }
  }
  return out;
}

std::vector<Place> referencesOf(const Found& found, const Unit& unit,
                                bool declaration) {
  std::vector<Place> out;
  if (const std::optional<VariableAt> v = variableAt(found);
      v && isLocal(v->number)) {
    variablePlaces(*found.program, v->number, out);
    return out;
  }
  if (found.onSequence) {
    const auto& blocks = found.program->blocks;
    if (declaration) {
      out.push_back(placeOf(found.block->range));
    }
    for (const Block& b : blocks) {
      if (b.stmt.gotoBlock &&
          &blocks[static_cast<std::size_t>(*b.stmt.gotoBlock)] == found.block) {
        out.push_back(placeOf(b.stmt.value ? b.stmt.value->range : b.range));
      }
    }
    return out;
  }
  const SharedName name = sharedNameOf(found);
  if (name.variable < 0 && name.program < 0) {
    return out;
  }
  std::set<std::uint32_t> files;
  for (const Program& p : unit.programs) {
    files.insert(p.file);
  }
  for (const std::uint32_t file : files) {
    const std::vector<Place> here = placesOf(name, unit, file, declaration);
    out.insert(out.end(), here.begin(), here.end());
  }
  return out;
}

std::vector<Symbol> documentSymbols(const toolchain::CompiledUnit& cu,
                                    std::uint32_t file) {
  std::vector<Symbol> out;
  const std::string_view text = cu.sources.text(file);
  for (const Program& p : cu.unit.programs) {
    if (p.file != file) {
      continue;
    }
    Symbol program{p.name,          "program", kFunctionSymbol,
                   wholeProgram(p), p.range,   {}};
    // The symbols the open DO loops hold, innermost last.
    std::vector<Symbol*> open{&program};
    std::vector<int> ends{-1};
    for (std::size_t i = 0; i < p.blocks.size(); ++i) {
      const Block& b = p.blocks[i];
      while (open.size() > 1 && ends.back() < static_cast<int>(i)) {
        open.pop_back();
        ends.pop_back();
      }
      if (b.seq >= 0) {
        const SourceRange n = sequenceRange(b, text);
        open.back()->children.push_back({fmt::format("N{}", b.seq),
                                         "label",
                                         kKeySymbol,
                                         b.range,
                                         n.length > 0 ? n : b.range,
                                         {}});
      }
      if (b.stmt.kind == StmtKind::While &&
          b.stmt.match > static_cast<int>(i)) {
        const Block& end = p.blocks[static_cast<std::size_t>(b.stmt.match)];
        SourceRange all = b.range;
        all.length = endOf(end.range) - b.range.begin.offset;
        open.back()->children.push_back({fmt::format("DO{}", b.stmt.loopId),
                                         b.stmt.cond ? "WHILE loop" : "loop",
                                         kNamespaceSymbol,
                                         all,
                                         b.range,
                                         {}});
        open.push_back(&open.back()->children.back());
        ends.push_back(b.stmt.match);
      }
    }
    out.push_back(std::move(program));
  }
  return out;
}

} // namespace mbc::lsp
