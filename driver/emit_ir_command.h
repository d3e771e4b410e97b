// `mbc emit-ir`, and the optimised module of the input that `mbc compile`
// and `mbc build` generate code from.
#pragma once

#include "driver/options.h"
#include "ir/ir.h"

namespace mbc::driver {

/// The optimised module of the input files (Macro B, or IR text with -x
/// mbir). Diagnostics and problems are printed; false when there were any.
bool loadModule(const Options& o, ir::Module& out);

/// `mbc emit-ir`: prints the module to standard output. Exit status.
int emitIrCommand(const Options& o);

} // namespace mbc::driver
