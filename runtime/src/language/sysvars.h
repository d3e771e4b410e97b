// The system variables, #1000 and up (spec §6): interface signals, tool and
// work offsets, #3000-series, modal information and positions.
#pragma once

#include <vector>

#include "context.h"

namespace mbc::rt {

/// Sets an input signal (#1000-#1031: 0 or 1) or word (#1032-#1035) from
/// outside the program: the profile or a preset. False for any other number
/// or value.
bool setInputSignal(mbrt_ctx& ctx, int number, double value);

/// #n for n >= 1000; PS0115 when n is no system variable of this machine.
mbrt_status readSystemVariable(mbrt_ctx& ctx, long n, Num* out);

/// #n = value for n >= 1000; PS0116 for read-only variables, PS0115 for
/// unknown numbers. `comment` is the block's message for #3000 and #3006.
mbrt_status writeSystemVariable(mbrt_ctx& ctx, long n, Num value,
                                const char* comment);

} // namespace mbc::rt
