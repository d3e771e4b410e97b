// mbc check's range analysis of alarms: the main program runs with its
// arguments in the ranges given (the rest vacant); the IR's range analysis
// (ir/passes/ranges.h) bounds every value, and each block that may raise
// one of the alarms it decides is reported, with the range of the value
// that leads there. Where a value has no bound, that is said: never a
// false "cannot alarm".
#pragma once

#include "frontend/diagnostics.h"

#include <string>

#include "toolchain/argument_ranges.h"
#include "toolchain/compile_unit.h"

namespace mbc::toolchain {

/// The blocks that may alarm, reported to `diags`; -1 (with `failure`
/// said) when the main program is not in the unit or the IR could not be
/// built. The unit must have no errors.
int checkAlarmRanges(const CompiledUnit& cu, const AlarmRangeRequest& request,
                     DiagnosticEngine& diags, std::string& failure);

} // namespace mbc::toolchain
