// The ranges of the values of a unit's programs when its main program runs
// with its arguments in given ranges (the rest vacant): the IR as the
// range analyses read it, and per function the IR's range analysis
// (ir/passes/ranges.h) from what its locals start with, which each call
// with its arguments' ranges widens. mbc check's analyses of alarms
// (alarm_ranges.h) and of where the tool goes (reach_box.h) read them.
#pragma once

#include "ir/ir.h"
#include "ir/passes/ranges.h"

#include <map>
#include <optional>
#include <string>

#include "toolchain/argument_ranges.h"
#include "toolchain/compile_unit.h"

namespace mbc::toolchain {

/// What an nc block calls by P: whether a code of it calls that way (M98,
/// M198, G65, G66, G66.1), and its P, a constant or the computed value.
struct CallByP {
  bool calls = false;
  std::optional<double> constant;
  std::optional<ir::ValueId> computed;
};

CallByP callByP(const ir::Function& f, const ir::Inst& nc);

/// The source range of line `line` of program `name`: its block (where
/// the analyses report an instruction of that line).
SourceRange blockAt(const Unit& unit, const std::string& name,
                    std::uint32_t line);

class UnitRanges {
public:
  UnitRanges() = default;
  // The facts point into the module.
  UnitRanges(const UnitRanges&) = delete;
  UnitRanges& operator=(const UnitRanges&) = delete;

  /// False, with `failure` said, when the IR cannot be built or the main
  /// program is not in the unit. The unit must have no errors.
  bool build(const CompiledUnit& cu, const AlarmRangeRequest& request,
             std::string& failure);

  /// Blocks of M99 (without P), M02 and M30 end in `ret`, and so does a
  /// block that writes #3000: no run goes on from them.
  const ir::Module& module() const { return module_; }

  const ir::Function& main() const { return *main_; }

  /// The facts of `f`; nullptr when no run enters it.
  const ir::RangeFacts* facts(const ir::Function& f) const;

  /// The function a constant P names; nullptr for none.
  const ir::Function* called(double p) const;

private:
  ir::Module module_;
  const ir::Function* main_ = nullptr;
  std::map<const ir::Function*, ir::RangeFacts> facts_;
};

} // namespace mbc::toolchain
