// The value ranges of a unit's programs (see value_ranges.h).
#include "toolchain/value_ranges.h"

#include "ir/lower.h"
#include <mbc/addresses.h>
#include <mbc/calling_codes.h>
#include <mbc/limits.h>

#include <algorithm>
#include <set>
#include <vector>

#include "toolchain/ir_pipeline.h"
#include "toolchain/main_program.h"

namespace mbc::toolchain {

namespace {

using ir::Range;
/// What a function's locals hold when it starts; empty: nothing known.
using Entry = std::vector<std::optional<Range>>;

/// A function whose start is widened more often than this gets nothing
/// known instead (a recursion, or a long chain of calls).
constexpr int kMaxVisits = 4;

Range join(const Range& a, const Range& b) {
  return Range{std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

/// The constant code `letter` of an nc, if it has one.
std::optional<double> codeOf(const ir::Function& f, const ir::Inst& nc,
                             char letter) {
  const auto& words = nc.get<ir::Words>().words;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const ir::Inst& value = f.insts[nc.ops[i]];
    if (words[i].letter == letter && value.op == ir::Op::Const) {
      return value.get<ir::Number>().value;
    }
  }
  return std::nullopt;
}

/// Prunes the ways out of a block that no run takes, for the analyses
/// alone: a block of M99 (without P), M02 or M30 leaves the program and
/// never goes on to the next, and #3000 stops the run in its block.
void dropDeadEdges(ir::Module& module) {
  for (ir::Function& f : module.functions) {
    for (const ir::Block& block : f.blocks) {
      const bool alarms = std::any_of(
          block.insts.begin(), block.insts.end(), [&](ir::ValueId id) {
            const ir::Inst& inst = f.insts[id];
            return inst.op == ir::Op::StVar &&
                   inst.get<ir::VarNumber>().number == kMacroAlarmVariable;
          });
      if (alarms) {
        ir::Inst& term = f.insts[block.insts.back()];
        term.op = ir::Op::Ret;
        term.ops.clear();
        term.targets.clear();
      }
    }
    for (ir::Inst& inst : f.insts) {
      if (inst.op != ir::Op::Resume) {
        continue;
      }
      const ir::Inst& nc = f.insts[inst.ops[0]];
      if (nc.op != ir::Op::Nc) {
        continue;
      }
      const auto& words = nc.get<ir::Words>().words;
      const bool jumps =
          std::any_of(words.begin(), words.end(),
                      [](const ir::AddressWord& w) { return w.letter == 'P'; });
      const std::optional<double> code = codeOf(f, nc, 'M');
      const bool leaves =
          code && (*code == 2 || *code == 30 || (*code == 99 && !jumps));
      if (leaves) {
        inst.op = ir::Op::Ret;
        inst.ops.clear();
        inst.targets.clear();
      }
    }
  }
}

/// What each function's locals start with, over every call a run may make:
/// the main program's from the request, a macro's from its calls'
/// arguments, and nothing known where a call cannot be followed.
class Entries {
public:
  explicit Entries(const UnitRanges& unit) : unit_(unit) {
    for (const ir::Function& f : unit.module().functions) {
      codeCalled_ = codeCalled_ || codeMayCallProgram(f.number);
    }
  }

  std::map<const ir::Function*, Entry> solve(Entry main) {
    enter(unit_.main(), std::move(main));
    while (!work_.empty()) {
      const ir::Function* f = *work_.begin();
      work_.erase(work_.begin());
      const ir::RangeFacts facts = ir::analyseRanges(*f, entries_.at(f));
      for (std::size_t b = 0; b < f->blocks.size(); ++b) {
        if (facts.reachable[b]) {
          for (ir::ValueId id : f->blocks[b].insts) {
            calls(*f, f->insts[id], facts);
          }
        }
      }
    }
    return entries_;
  }

private:
  /// Joins `entry` into what `f` starts with; queues it when that grew.
  void enter(const ir::Function& f, Entry entry) {
    auto [it, added] = entries_.try_emplace(&f, entry);
    if (!added) {
      Entry& known = it->second;
      if (known.empty()) {
        return;
      }
      Entry joined;
      if (!entry.empty() && ++visits_[&f] <= kMaxVisits) {
        joined = known;
        for (std::size_t i = 0; i < joined.size(); ++i) {
          joined[i] = joined[i] && entry[i]
                          ? std::optional(join(*joined[i], *entry[i]))
                          : std::nullopt;
        }
      }
      if (joined == known) {
        return;
      }
      known = std::move(joined);
    }
    work_.insert(&f);
  }

  void enterAll() {
    for (const ir::Function& f : unit_.module().functions) {
      enter(f, {});
    }
  }

  /// The programs an instruction calls, and what their locals start with.
  void calls(const ir::Function& f, const ir::Inst& inst,
             const ir::RangeFacts& facts) {
    if (inst.op == ir::Op::CallMacro) {
      const ir::Inst& p = f.insts[inst.ops[0]];
      if (p.op != ir::Op::Const) {
        enterAll();
      } else if (const ir::Function* callee =
                     unit_.called(p.get<ir::Number>().value)) {
        enter(*callee, arguments(inst, facts.values));
      }
      return;
    }
    if (inst.op != ir::Op::Nc) {
      return;
    }
    // A code may call O9000-O9029 from any block, with nothing known.
    if (codeCalled_ && !codesEntered_) {
      codesEntered_ = true;
      for (const ir::Function& g : unit_.module().functions) {
        if (codeMayCallProgram(g.number)) {
          enter(g, {});
        }
      }
    }
    const CallByP call = callByP(f, inst);
    if (!call.calls) {
      return;
    }
    if (call.computed) {
      enterAll();
    } else if (call.constant) {
      if (const ir::Function* callee = unit_.called(*call.constant)) {
        enter(*callee, {}); // an M98's locals are its caller's
      }
    }
  }

  /// What a G65's macro starts with: its arguments' ranges, the rest
  /// vacant (0). A literal without a decimal point may be scaled down to
  /// the least input increment (X10 is 0.010 mm or 0.0010 inch).
  static Entry arguments(const ir::Inst& call,
                         const std::vector<Range>& values) {
    Entry entry(kLocalCount, Range{0, 0});
    const auto& words = call.get<ir::Words>().words;
    IjkSets sets;
    for (std::size_t i = 0; i < words.size(); ++i) {
      const int local = nextArgumentLocal(words[i].letter, sets);
      if (local < 1 || local > kLocalCount) {
        continue;
      }
      Range r = values[call.ops[ir::firstWordOperand(call.op) + i]];
      if (words[i].kind == ir::WordKind::Int) {
        r = join(r, Range{r.lo / 10000, r.hi / 10000});
      }
      entry[static_cast<std::size_t>(local - 1)] = r;
    }
    return entry;
  }

  const UnitRanges& unit_;
  bool codeCalled_ = false;
  bool codesEntered_ = false;
  std::map<const ir::Function*, Entry> entries_;
  std::map<const ir::Function*, int> visits_;
  std::set<const ir::Function*> work_;
};

} // namespace

CallByP callByP(const ir::Function& f, const ir::Inst& nc) {
  CallByP call;
  const auto& words = nc.get<ir::Words>().words;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const ir::Inst& value = f.insts[nc.ops[i]];
    const bool constant = value.op == ir::Op::Const;
    const double v = constant ? value.get<ir::Number>().value : 0;
    if (words[i].letter == 'P') {
      call.constant = constant ? std::optional(v) : std::nullopt;
      call.computed = constant ? std::nullopt : std::optional(nc.ops[i]);
    } else if (constant && callsByP(words[i].letter, v)) {
      call.calls = true;
    }
  }
  return call;
}

bool UnitRanges::build(const CompiledUnit& cu, const AlarmRangeRequest& request,
                       std::string& failure) {
  if (!buildModule(cu, false, module_) ||
      !optimizeModule(module_, IrPasses{})) {
    failure = "the IR of the input could not be built";
    return false;
  }
  dropDeadEdges(module_);
  // Functions are lowered in the order of the unit's programs.
  const int index = findMain(cu.unit, request.mainProgram);
  if (index < 0) {
    failure = request.mainProgram.empty()
                  ? "the input has no programs"
                  : missingMainMessage(cu.unit, request.mainProgram);
    return false;
  }
  main_ = &module_.functions[static_cast<std::size_t>(index)];
  // The main program's locals are vacant but for the arguments.
  Entry entry(kLocalCount, Range{0, 0});
  IjkSets sets;
  for (const ArgumentRange& arg : request.args) {
    const int local = nextArgumentLocal(arg.letter, sets);
    if (local >= 1 && local <= kLocalCount) {
      entry[static_cast<std::size_t>(local - 1)] = Range{arg.lo, arg.hi};
    }
  }
  for (const auto& [f, start] : Entries(*this).solve(std::move(entry))) {
    facts_.emplace(f, ir::analyseRanges(*f, start));
  }
  return true;
}

const ir::RangeFacts* UnitRanges::facts(const ir::Function& f) const {
  const auto it = facts_.find(&f);
  return it != facts_.end() ? &it->second : nullptr;
}

/// The source range of line `line` of program `name`: its block.
SourceRange blockAt(const Unit& unit, const std::string& name,
                    std::uint32_t line) {
  for (const Program& p : unit.programs) {
    if (p.name != name) {
      continue;
    }
    for (const Block& b : p.blocks) {
      if (b.line == static_cast<int>(line)) {
        return b.range;
      }
    }
    return p.range;
  }
  return {};
}

const ir::Function* UnitRanges::called(double p) const {
  return module_.numbered(calledProgramNumber(p).value_or(-1));
}

} // namespace mbc::toolchain
