// The value model of Custom Macro B (spec §2.3, §13): a variable holds either
// a 64-bit IEEE double or "vacant". Vacant is one reserved quiet-NaN bit
// pattern, so a value is a plain double everywhere (interpreter, IR, LLVM)
// and no legal result is ever a NaN (domain errors become alarms).
#pragma once

#include <bit>
#include <cstdint>

namespace mbc {

using Num = double;

inline constexpr std::uint64_t kVacantBits = 0x7ff8'0000'0bad'cafeULL;

inline Num vacant() {
  return std::bit_cast<double>(kVacantBits);
}

/// Every NaN counts as vacant: arithmetic never produces one.
inline bool isVacant(Num v) {
  return v != v;
}

/// The value an operator sees: vacant behaves as 0 except in EQ/NE and plain
/// assignment (spec §2.3b).
inline double numeric(Num v) {
  return isVacant(v) ? 0.0 : v;
}

} // namespace mbc
