// The range analysis of alarms (see alarm_ranges.h).
#include "toolchain/alarm_ranges.h"

#include <mbc/alarm.h>
#include <mbc/arith.h>
#include <mbc/limits.h>
#include <mbc/sysvars.h>

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace mbc::toolchain {

namespace {

using ir::Range;

/// A range of whole numbers wider than this is not searched value by
/// value (variable and program numbers).
constexpr double kMaxSearched = 10000;

bool bounded(const Range& r) {
  return std::isfinite(r.lo) && std::isfinite(r.hi);
}

bool holds(const Range& r, double x) {
  return r.lo <= x && x <= r.hi;
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
  explicit Analysis(const UnitRanges& unit) : unit_(unit) {}

  void run() {
    for (const ir::Function& f : unit_.module().functions) {
      const ir::RangeFacts* facts = unit_.facts(f);
      if (facts == nullptr) {
        continue;
      }
      for (std::size_t b = 0; b < f.blocks.size(); ++b) {
        if (facts->reachable[b]) {
          for (ir::ValueId id : f.blocks[b].insts) {
            check(f, f.insts[id], facts->values);
          }
        }
      }
    }
  }

  const std::vector<Finding>& findings() const { return findings_; }

private:
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
        if (inst.get<ir::VarNumber>().number == kMacroAlarmVariable) {
          add(f, inst, fmt::format("the alarm of #{}", kMacroAlarmVariable),
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
    const bool known = everyNumber(
        p, [&](int n) { return unit_.module().numbered(n) != nullptr; });
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

  const UnitRanges& unit_;
  std::vector<Finding> findings_;
};

} // namespace

int checkAlarmRanges(const CompiledUnit& cu, const UnitRanges& unit,
                     DiagnosticEngine& diags) {
  Analysis analysis(unit);
  analysis.run();
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
