// `mbc batch FILE... --params TABLE.csv --out DIR [-j N] [--shard I/N]
// [--combined]`: the main program run once per row of a parameter table, the
// rows spread over threads that share one compiled program (docs/batch.md).
#pragma once

#include "driver/options.h"

namespace mbc::driver {

/// 0 when every row ended normally, 3 when some row stopped with an alarm
/// (the others still ran), 1 source errors, 2 a bad table, option or lost
/// output, 4 internal error, 128 + a signal that stopped the batch.
int batchCommand(const Options& o);

} // namespace mbc::driver
