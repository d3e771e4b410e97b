// `mbc check`: the diagnostics of the input and, with --arg/--prove, the
// blocks that may alarm over the argument ranges given; with --machine
// too, where the tool may go on that machine (toolchain/reach_box.h).
#pragma once

#include "driver/options.h"

namespace mbc::driver {

/// Exit status: 0, or 1 when the input has errors (or, with --prove, a
/// block may alarm), 2 when the profile cannot be read.
int checkCommand(const Options& o);

} // namespace mbc::driver
