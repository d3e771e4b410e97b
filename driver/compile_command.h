// `mbc compile` and `mbc build`: ahead-of-time compilation to an object
// (with an optional C header) or to a standalone executable.
#pragma once

#include "driver/options.h"

namespace mbc::driver {

/// Exit status: 0, 1 (source errors), 4 (LLVM or the linker failed).
int compileCommand(const Options& o);
int buildCommand(const Options& o);

} // namespace mbc::driver
