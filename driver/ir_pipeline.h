// The IR half of the pipeline: lowering a checked unit, verifying the result
// (a verifier failure is an internal compiler error, not user input) and
// running the passes.
#pragma once

#include "driver/compile_unit.h"
#include "driver/options.h"
#include "ir/ir.h"

namespace mbc::driver {

/// Lowers and verifies; on a verifier failure prints it and returns false.
/// --trace lowers with a `trace` instruction per statement.
bool buildModule(const CompiledUnit& cu, const Options& o, ir::Module& out);

/// Runs the pass pipeline as the options say (nothing with --no-opt), then
/// verifies once more. Prints what went wrong and returns false on failure.
bool optimizeModule(ir::Module& m, const Options& o);

/// The optimised module of the input files (Macro B, or IR text with -x
/// mbir). Diagnostics and problems are printed; false when there were any.
bool loadModule(const Options& o, ir::Module& out);

/// `mbc emit-ir`: prints the module to standard output. Exit status.
int emitIrCommand(const Options& o);

} // namespace mbc::driver
