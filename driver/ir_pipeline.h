// The IR half of the pipeline: lowering a checked unit and verifying the
// result (a verifier failure is an internal compiler error, not user input).
#pragma once

#include "driver/compile_unit.h"
#include "ir/ir.h"

namespace mbc::driver {

/// Lowers and verifies; on a verifier failure prints it and returns false.
bool buildModule(const CompiledUnit& cu, ir::Module& out);

/// `mbc emit-ir`: prints the module to standard output. Exit status.
int emitIrCommand(const std::vector<std::string>& files);

} // namespace mbc::driver
