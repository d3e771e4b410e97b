// The range analysis of alarms (see alarm_ranges.h).
#include "toolchain/alarm_ranges.h"

#include "ir/lower.h"
#include "ir/passes/ranges.h"
#include <mbc/addresses.h>
#include <mbc/alarm.h>
#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/limits.h>
#include <mbc/sysvars.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "toolchain/ir_pipeline.h"
#include "toolchain/main_program.h"

namespace mbc::toolchain {

namespace {

using ir::Range;
/// What a function's locals hold when it starts; empty: nothing known.
using Entry = std::vector<std::optional<Range>>;

/// A range of whole numbers wider than this is not searched value by
/// value (variable and program numbers).
constexpr double kMaxSearched = 10000;
/// A function whose start is widened more often than this gets nothing
/// known instead (a recursion, or a long chain of calls).
constexpr int kMaxVisits = 4;
constexpr int kAlarmVariable = 3000;

bool bounded(const Range& r) {
  return std::isfinite(r.lo) && std::isfinite(r.hi);
}

bool holds(const Range& r, double x) {
  return r.lo <= x && x <= r.hi;
}

Range join(const Range& a, const Range& b) {
  return Range{std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

std::string rangeText(const Range& r) {
  if (!bounded(r)) {
    return "has no bound the analysis can find (it depends on a value the "
           "ranges given do not bound)";
  }
  if (r.lo == r.hi) {
    return fmt::format("is {}", r.lo);
  }
  return fmt::format("takes {} to {}", r.lo, r.hi);
}

/// Whether every whole number that `r` rounds to passes `ok`; false when
/// there are too many to try.
template <typename Ok> bool everyNumber(const Range& r, Ok ok) {
  if (!bounded(r)) {
    return false;
  }
  const double lo = roundHalfAway(r.lo);
  const double hi = roundHalfAway(r.hi);
  if (hi - lo > kMaxSearched) {
    return false;
  }
  for (double n = lo; n <= hi; ++n) {
    if (!ok(static_cast<int>(n))) {
      return false;
    }
  }
  return true;
}

bool readable(int n) {
  return variableAccess(n) != VarAccess::Missing &&
         !unmodelledVariable(n, nullptr);
}

bool writable(int n) {
  return variableAccess(n) == VarAccess::ReadWrite &&
         !unmodelledVariable(n, nullptr);
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

/// What an nc block calls by P: whether a code of it calls that way (M98,
/// M198, G65, G66, G66.1), and its P, a constant or the computed value.
struct CallByP {
  bool calls = false;
  std::optional<double> constant;
  std::optional<ir::ValueId> computed;
};

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

/// The function a constant P names; nullptr for none.
const ir::Function* calledFunction(const ir::Module& m, double p) {
  return m.numbered(calledProgramNumber(p).value_or(-1));
}

/// Prunes the ways out of a block that no run takes, for the analysis
/// alone: a block of M99 (without P), M02 or M30 leaves the program and
/// never goes on to the next, and #3000 stops the run in its block.
void dropDeadEdges(ir::Module& module) {
  for (ir::Function& f : module.functions) {
    for (const ir::Block& block : f.blocks) {
      const bool alarms = std::any_of(
          block.insts.begin(), block.insts.end(), [&](ir::ValueId id) {
            const ir::Inst& inst = f.insts[id];
            return inst.op == ir::Op::StVar &&
                   inst.get<ir::VarNumber>().number == kAlarmVariable;
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

/// One block that may alarm.
struct Finding {
  std::string function;
  std::uint32_t line = 0;
  std::string alarm; // "PS0112 ZERO DIVIDE"
  std::string why;
};

std::string alarmText(AlarmId id) {
  return fmt::format("{} {}", alarmCode(id, 0), alarmInfo(id).message);
}

class Analysis {
public:
  explicit Analysis(const ir::Module& m) : m_(m) {
    for (const ir::Function& f : m.functions) {
      codeCalled_ = codeCalled_ || codeMayCallProgram(f.number);
    }
  }

  void start(const ir::Function& main, Entry entry) {
    enter(main, std::move(entry));
    while (!work_.empty()) {
      const ir::Function* f = *work_.begin();
      work_.erase(work_.begin());
      visit(*f, false);
    }
    // Every start is final now: report with it.
    for (const auto& [f, known] : entries_) {
      visit(*f, true);
    }
  }

  const std::vector<Finding>& findings() const { return findings_; }

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
    for (const ir::Function& f : m_.functions) {
      enter(f, {});
    }
  }

  void visit(const ir::Function& f, bool report) {
    const ir::RangeFacts facts = ir::analyseRanges(f, entries_.at(&f));
    for (std::size_t b = 0; b < f.blocks.size(); ++b) {
      if (!facts.reachable[b]) {
        continue;
      }
      for (ir::ValueId id : f.blocks[b].insts) {
        const ir::Inst& inst = f.insts[id];
        if (report) {
          check(f, inst, facts.values);
        } else {
          calls(f, inst, facts);
        }
      }
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
                     calledFunction(m_, p.get<ir::Number>().value)) {
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
      for (const ir::Function& g : m_.functions) {
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
      if (const ir::Function* callee = calledFunction(m_, *call.constant)) {
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

  void add(const ir::Function& f, const ir::Inst& inst, std::string alarm,
           std::string why) {
    findings_.push_back({f.name, inst.line, std::move(alarm), std::move(why)});
  }

  void check(const ir::Function& f, const ir::Inst& inst,
             const std::vector<Range>& values) {
    const auto operand = [&](std::size_t i) { return values[inst.ops[i]]; };
    switch (inst.op) {
      case ir::Op::Div:
        if (holds(operand(1), 0)) {
          add(f, inst, alarmText(AlarmId::ZeroDivide),
              "the divisor " + rangeText(operand(1)));
        }
        return;
      case ir::Op::Mod:
        if (operand(1).lo < 0.5 && operand(1).hi > -0.5) {
          add(f, inst, alarmText(AlarmId::ZeroDivide),
              "MOD's divisor " + rangeText(operand(1)));
        }
        return;
      case ir::Op::Fn:
        checkFunction(f, inst, values);
        return;
      case ir::Op::LdInd:
      case ir::Op::Adp:
        if (!everyNumber(operand(0), readable)) {
          add(f, inst, alarmText(AlarmId::VariableOutOfRange),
              "the variable number of #[...] " + rangeText(operand(0)));
        }
        return;
      case ir::Op::StInd:
        if (!everyNumber(operand(0), writable)) {
          add(f, inst, alarmText(AlarmId::VariableOutOfRange),
              "the variable number of #[...]= " + rangeText(operand(0)));
        }
        return;
      case ir::Op::StVar:
        if (inst.get<ir::VarNumber>().number == kAlarmVariable) {
          add(f, inst, fmt::format("the alarm of #{}", kAlarmVariable),
              "a run with the arguments given may reach it");
        }
        return;
      case ir::Op::CallMacro:
        checkProgramNumber(f, inst, operand(0));
        return;
      case ir::Op::Nc:
        checkBlock(f, inst, values);
        return;
      default:
        return;
    }
  }

  void checkFunction(const ir::Function& f, const ir::Inst& inst,
                     const std::vector<Range>& values) {
    const Builtin fn = inst.get<ir::BuiltinFn>().fn;
    const Range x = values[inst.ops[0]];
    const auto domain = [&](bool outside, const char* name) {
      if (outside) {
        add(f, inst, alarmText(AlarmId::ArgumentOutOfRange),
            fmt::format("{}'s argument {}", name, rangeText(x)));
      }
    };
    switch (fn) {
      case Builtin::Sqrt:
        domain(x.lo < 0, "SQRT");
        return;
      case Builtin::Asin:
        domain(x.lo < -1 || x.hi > 1, "ASIN");
        return;
      case Builtin::Acos:
        domain(x.lo < -1 || x.hi > 1, "ACOS");
        return;
      case Builtin::Ln:
        domain(x.lo <= 0, "LN");
        return;
      case Builtin::Tan:
        // COS is 0 at 90 + 180k degrees.
        if (!bounded(x) ||
            std::ceil((x.lo - 90) / 180) <= std::floor((x.hi - 90) / 180)) {
          add(f, inst, alarmText(AlarmId::ZeroDivide),
              "TAN's argument " + rangeText(x) + ", which reaches 90 + 180k");
        }
        return;
      case Builtin::Pow:
      case Builtin::Exp:
      case Builtin::Bin:
      case Builtin::Bcd:
      case Builtin::Adp:
        add(f, inst, "an alarm of its function",
            "mbc's range analysis does not decide the alarms of POW, EXP, "
            "BIN, BCD and ADP");
        return;
      default:
        return;
    }
  }

  void checkProgramNumber(const ir::Function& f, const ir::Inst& inst,
                          const Range& p) {
    const bool known =
        everyNumber(p, [&](int n) { return m_.numbered(n) != nullptr; });
    if (!known) {
      add(f, inst, alarmText(AlarmId::ProgramNotFound),
          "the called program's number " + rangeText(p));
    }
  }

  void checkBlock(const ir::Function& f, const ir::Inst& inst,
                  const std::vector<Range>& values) {
    const auto& words = inst.get<ir::Words>().words;
    for (std::size_t i = 0; i < words.size(); ++i) {
      const Range& r = values[inst.ops[i]];
      // A bare variable may be vacant (no F word): only a number counts.
      if (words[i].letter == 'F' &&
          f.insts[inst.ops[i]].type == ir::Type::Num && holds(r, 0)) {
        add(f, inst, alarmText(AlarmId::FeedZero),
            "F " + rangeText(r) + ": a cutting move at feed 0 alarms");
      }
    }
    const CallByP call = callByP(f, inst);
    if (call.calls && call.computed) {
      checkProgramNumber(f, inst, values[*call.computed]);
    }
  }

  const ir::Module& m_;
  bool codeCalled_ = false;
  bool codesEntered_ = false;
  std::map<const ir::Function*, Entry> entries_;
  std::map<const ir::Function*, int> visits_;
  std::set<const ir::Function*> work_;
  std::vector<Finding> findings_;
};

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

} // namespace

int checkAlarmRanges(const CompiledUnit& cu, const AlarmRangeRequest& request,
                     DiagnosticEngine& diags, std::string& failure) {
  ir::Module module;
  if (!buildModule(cu, false, module) || !optimizeModule(module, IrPasses{})) {
    failure = "the IR of the input could not be built";
    return -1;
  }
  dropDeadEdges(module);
  // Functions are lowered in the order of the unit's programs.
  const int index = findMain(cu.unit, request.mainProgram);
  if (index < 0) {
    failure = request.mainProgram.empty()
                  ? "the input has no programs"
                  : missingMainMessage(cu.unit, request.mainProgram);
    return -1;
  }
  const ir::Function* main = &module.functions[static_cast<std::size_t>(index)];
  // The main program's locals are vacant but for the arguments.
  Entry entry(kLocalCount, Range{0, 0});
  IjkSets sets;
  for (const ArgumentRange& arg : request.args) {
    const int local = nextArgumentLocal(arg.letter, sets);
    if (local >= 1 && local <= kLocalCount) {
      entry[static_cast<std::size_t>(local - 1)] = Range{arg.lo, arg.hi};
    }
  }
  Analysis analysis(module);
  analysis.start(*main, std::move(entry));
  std::set<std::tuple<std::string, std::uint32_t, std::string>> said;
  int count = 0;
  for (const Finding& finding : analysis.findings()) {
    if (!said.emplace(finding.function, finding.line, finding.alarm).second) {
      continue;
    }
    diags.report(DiagKind::RangeAlarm,
                 blockAt(cu.unit, finding.function, finding.line),
                 finding.alarm, finding.why);
    ++count;
  }
  return count;
}

} // namespace mbc::toolchain
