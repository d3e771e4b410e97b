// mbc check's range analysis of alarms: the main program runs with its
// arguments in the ranges given (the rest vacant); the IR's range analysis
// (ir/passes/ranges.h) bounds every value, and each block that may raise
// one of the alarms it decides is reported, with the range of the value
// that leads there. Where a value has no bound, that is said: never a
// false "cannot alarm".
#pragma once

#include "frontend/diagnostics.h"

#include "toolchain/compile_unit.h"
#include "toolchain/value_ranges.h"

namespace mbc::toolchain {

/// The blocks that may alarm, reported to `diags`.
int checkAlarmRanges(const CompiledUnit& cu, const UnitRanges& unit,
                     DiagnosticEngine& diags);

} // namespace mbc::toolchain
