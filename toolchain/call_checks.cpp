// Calls held against their callees (see call_checks.h).
#include "toolchain/call_checks.h"

#include "frontend/called_programs.h"
#include "ir/arguments_read.h"
#include "ir/lower.h"
#include <mbc/addresses.h>
#include <mbc/limits.h>

#include <map>
#include <string>

namespace mbc::toolchain {

namespace {

/// #12: the local L would set if it were an argument (spec §5.2 leaves the
/// gap); only a third I J K set's K reaches it.
constexpr int kRepeatLocal = 12;

/// The number of the program a G65 or G66 calls, when it is a constant (a
/// call by name has its program's number by now).
std::optional<int> calledNumber(const Stmt& s) {
  const Expr* p = nullptr;
  if (s.kind == StmtKind::MacroCall) {
    p = s.program.get();
  } else {
    for (const Word& w : s.words) {
      if (w.letter == 'P') {
        p = w.value.get();
      }
    }
  }
  if (p == nullptr || p->kind != ExprKind::Number) {
    return std::nullopt;
  }
  return calledProgramNumber(p->number);
}

/// The L of a G65 or G66, where it is written.
const SourceRange* repeatRange(const Stmt& s) {
  if (s.kind == StmtKind::MacroCall) {
    return s.repeat ? &s.repeat->range : nullptr;
  }
  for (const Word& w : s.words) {
    if (w.letter == 'L') {
      return &w.range;
    }
  }
  return nullptr;
}

} // namespace

void checkCallsAgainstCallees(const CompiledUnit& cu, DiagnosticEngine& diags) {
  const ir::Module module = ir::lower(cu.unit, cu.sources);
  // By the program's number, which a call by name has by now too (the IR
  // numbers named programs -1: they are found by name).
  std::map<std::string, const ir::Function*, std::less<>> byName;
  for (const ir::Function& f : module.functions) {
    byName.emplace(f.name, &f);
  }
  std::map<int, const ir::Function*> functions;
  for (const Program& p : cu.unit.programs) {
    if (const auto f = byName.find(p.name); f != byName.end()) {
      functions.emplace(p.number, f->second);
    }
  }
  std::map<int, ir::ArgumentsRead> reads;
  for (const Program& program : cu.unit.programs) {
    for (const Block& b : program.blocks) {
      const std::vector<const Word*> args = callArguments(b.stmt);
      const std::optional<int> number =
          args.empty() && b.stmt.kind != StmtKind::MacroCall
              ? std::nullopt
              : calledNumber(b.stmt);
      const auto callee = number ? functions.find(*number) : functions.end();
      if (callee == functions.end()) {
        continue;
      }
      auto [read, added] = reads.try_emplace(*number);
      if (added) {
        read->second = ir::argumentsRead(module, *callee->second);
      }
      const ir::ArgumentsRead& r = read->second;
      if (r.computed) {
        continue;
      }
      const std::string name = callee->second->name;
      const std::vector<int> locals = argumentLocals(args);
      bool setsRepeatLocal = false;
      for (std::size_t i = 0; i < args.size(); ++i) {
        const int local = locals[i];
        if (local <= 0 || local > kLocalCount) {
          continue;
        }
        setsRepeatLocal = setsRepeatLocal || local == kRepeatLocal;
        if (!r.locals.test(static_cast<std::size_t>(local - 1))) {
          diags.report(DiagKind::UnusedArgument, args[i]->range, name, local,
                       addressText(args[i]->letter));
        }
      }
      const SourceRange* repeat = repeatRange(b.stmt);
      if (repeat != nullptr && !setsRepeatLocal && !r.computedWrite &&
          r.locals.test(kRepeatLocal - 1) &&
          !r.written.test(kRepeatLocal - 1)) {
        diags.report(DiagKind::RepeatCountRead, *repeat, name, kRepeatLocal);
      }
    }
  }
}

} // namespace mbc::toolchain
