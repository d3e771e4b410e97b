// The interface signals a macro reads as variables (spec §6.2): what a
// machine profile may set and the variables read.
#pragma once

#include <cmath>

namespace mbc {

/// The input signals: #1000-#1031 one each, #1032-#1035 32 at a time.
inline constexpr int kFirstInputSignal = 1000;
inline constexpr int kFirstInputWord = 1032;
inline constexpr int kLastInputWord = 1035;

/// A value 32 signals can hold: a whole signed 32-bit number.
inline bool isSignalWord(double v) {
  return v == std::trunc(v) && v >= -2147483648.0 && v <= 2147483647.0;
}

} // namespace mbc
