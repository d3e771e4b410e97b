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
  std::map<std::string, const ir::Function*, std::less<>> functions;
  for (const ir::Function& f : module.functions) {
    functions.emplace(f.name, &f);
  }
  std::map<const ir::Function*, ir::ArgumentsRead> reads;
  for (const Program& program : cu.unit.programs) {
    for (const Block& b : program.blocks) {
      const std::vector<const Word*> args = callArguments(b.stmt);
      const std::optional<ProgramCall> call =
          args.empty() && b.stmt.kind != StmtKind::MacroCall
              ? std::nullopt
              : programCallOf(b.stmt);
      // A G65 or G66 names one program, by number or name.
      const auto callee =
          call ? functions.find(call->programs.front().name) : functions.end();
      if (callee == functions.end()) {
        continue;
      }
      auto [read, added] = reads.try_emplace(callee->second);
      if (added) {
        read->second = ir::argumentsRead(module, *callee->second);
      }
      const ir::ArgumentsRead& r = read->second;
      if (r.computed) {
        continue;
      }
      const std::string& name = callee->first;
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
