// The system variables, #1000 and up (spec §6): interface signals, tool and
// work offsets, #3000-series, modal information and positions.
#pragma once

#include <cmath>

#include "context.h"

namespace mbc::rt {

/// The input signals: #1000-#1031 one each, #1032-#1035 32 at a time.
inline constexpr int kFirstInputSignal = 1000;
inline constexpr int kFirstInputWord = 1032;
inline constexpr int kLastInputWord = 1035;

/// A value 32 signals can hold: a whole signed 32-bit number.
inline bool isSignalWord(double v) {
  return v == std::trunc(v) && v >= -2147483648.0 && v <= 2147483647.0;
}

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
