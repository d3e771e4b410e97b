// mbc check's analysis of where the tool goes: with the main program's
// arguments in the ranges given (value_ranges.h) and the machine of a
// profile (machine_facts.h), the machine coordinates each move of a run
// may take each axis to, from the modal state each block may run in: the
// distance mode, the work coordinate system, the tool length offset, the
// plane, canned cycles and cutter compensation, through calls. Each block
// that may take an axis past an end of its stored stroke (1320/1321) is
// reported, with how far. Where the analysis cannot follow the tool (a
// frame, data written at run time, a code it does not model) it says so
// at that block: never a false "within the strokes".
#pragma once

#include "frontend/diagnostics.h"

#include <string>
#include <vector>

#include "toolchain/compile_unit.h"
#include "toolchain/machine_facts.h"
#include "toolchain/value_ranges.h"

namespace mbc::toolchain {

struct Reach {
  int findings = 0; // blocks reported
  // Whether the analysis followed the tool through every move a run may
  // make; `box` holds then every machine position it may take, per axis.
  bool decided = true;
  std::vector<ir::Range> box;
};

Reach checkReach(const CompiledUnit& cu, const UnitRanges& unit,
                 const MachineFacts& machine, DiagnosticEngine& diags);

} // namespace mbc::toolchain
