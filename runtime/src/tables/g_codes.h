// The G codes of a FANUC 0i-MF (M series) with their names, so that a G code
// mbc does not execute yet is told apart from one FANUC does not have.
#pragma once

#include <mbc/g_codes.h>

#include <span>

namespace mbc::rt {

struct GCodeInfo {
  int tenths;    // G54.1 -> 541
  bool modelled; // mbc executes it; otherwise the run stops with MBC0001
  const char* name;
};

/// The look-ahead, AI contour control, smoothing and servo switches
/// (look_ahead.h), in tenths: group 00 codes whose words are settings, not
/// a move.
inline constexpr int kG05 = 50;
inline constexpr int kG051 = 51;
inline constexpr int kG054 = 54;
inline constexpr int kG08 = 80;

inline constexpr bool isLookAheadCode(int tenths) {
  return tenths == kG05 || tenths == kG051 || tenths == kG054 || tenths == kG08;
}

/// The FANUC G code with this number in tenths, or nullptr if there is none.
const GCodeInfo* findGCode(int tenths);

/// Every code of the list, by number (docs/control-tables.md).
std::span<const GCodeInfo> millGCodeList();

} // namespace mbc::rt
