// The IR half of the pipeline: lowering a checked unit, verifying the result
// (a verifier failure is an internal compiler error, not user input) and
// running the passes.
#pragma once

#include "ir/ir.h"

#include "toolchain/compile_unit.h"
#include "toolchain/request.h"

namespace mbc::toolchain {

/// Lowers and verifies; on a verifier failure prints it and returns false.
/// `trace` lowers with a `trace` instruction per statement.
bool buildModule(const CompiledUnit& cu, bool trace, ir::Module& out);

/// Runs the pass pipeline (nothing when passes.run is false), then verifies
/// once more. Prints what went wrong and returns false on failure.
bool optimizeModule(ir::Module& m, const IrPasses& passes);

/// Verifies a module, printing each problem after "mbc: <what>: "; false
/// when there was any.
bool verifyModule(const ir::Module& m, const char* what);

} // namespace mbc::toolchain
