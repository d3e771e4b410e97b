// mbc check's calls held against their callees: the IR of the unit says
// which locals each program reads and writes (ir/arguments_read.h), so a
// G65 or G66 can be compared with the macro it calls.
#pragma once

#include "frontend/diagnostics.h"

#include "toolchain/compile_unit.h"

namespace mbc::toolchain {

/// Warns of arguments the called macro never reads (the value is lost) and
/// of a call's L when the macro reads #12 as if L passed it (L is the
/// repeat count). Calls of a macro that reads or writes locals by a
/// computed number, or calls subprograms by a computed P, are left alone:
/// nothing certain can be said. The unit must have no errors.
void checkCallsAgainstCallees(const CompiledUnit& cu, DiagnosticEngine& diags);

} // namespace mbc::toolchain
