// The codes of a lathe's own functions (tables/g_codes.def) that the
// lathe's cycles and threading read, and how a G code system writes them.
#pragma once

#include "g_codes.h"

namespace mbc::rt {

inline constexpr int kLatheG10 = kLatheOwnCode + 100; // offsets

/// The lathe's group 01 codes of their own, as ModalState::motion holds
/// them (system A's numbers): G32 and the single cycles (lathe_cycles.h).
inline constexpr int kThreadingMotion = 32;
inline constexpr int kVariableLeadMotion = 34; // G34
inline constexpr int kTurningCycleMotion = 90;
inline constexpr int kThreadCycleMotion = 92;
inline constexpr int kFacingCycleMotion = 94;

/// Whether moves in a motion mode cut a thread: F is the lead.
inline bool cutsThread(int motion) {
  return motion == kThreadingMotion || motion == kVariableLeadMotion ||
         motion == kThreadCycleMotion;
}

inline bool isSingleCycle(int motion) {
  return motion == kTurningCycleMotion || motion == kThreadCycleMotion ||
         motion == kFacingCycleMotion;
}

/// A code of g_codes.def as a lathe's G code system ('A', 'B', 'C') writes
/// it, for alarms and labels: 98 for feed per minute (940) in system A, 94
/// in B and C; 0 for none.
inline double writtenLatheCode(char system, int code) {
  const int tenths = columnTenths(system, code);
  return tenths != kNo ? tenths / 10.0 : 0.0;
}

} // namespace mbc::rt
