// The G codes of a FANUC 0i-TF (T series, lathes) in G code systems A, B
// and C (parameter 3401#6 GSB, #7 GSC): what each means, the modal group
// #4001+ reads it in, and whether mbc executes it.
#pragma once

#include <span>

#include "context.h"

namespace mbc::rt {

/// A lathe's own functions, numbered 10000 plus their code in system A
/// (tenths); codes a mill has too keep the mill's number.
inline constexpr int kLatheOwnCode = 10000;
inline constexpr int kLatheThreading = kLatheOwnCode + 320;    // G32
inline constexpr int kLatheVariableLead = kLatheOwnCode + 340; // G34
inline constexpr int kLatheTurningCycle = kLatheOwnCode + 900; // G90
inline constexpr int kLatheThreadCycle = kLatheOwnCode + 920;  // G92
inline constexpr int kLatheFacingCycle = kLatheOwnCode + 940;  // G94
inline constexpr int kLatheG10 = kLatheOwnCode + 100;          // offsets

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

/// A code missing from one G code system.
inline constexpr int kNoLatheCode = -1;

/// One row of the lathe's G code list.
struct LatheGCode {
  int a, b, c; // tenths in systems A, B and C (kNoLatheCode: none)
  int code;    // latheCode: a mill's number or kLatheOwnCode + A's
  bool modelled;
  const char* name;
};

/// Every row, in system A's order (docs/control-tables.md).
std::span<const LatheGCode> latheGCodeList();

/// What a G word (tenths) of a lathe's program does, in the numbering
/// applyGCode executes: a mill's code where the function is the same
/// (system A's G50 is 920, a coordinate system setting like a mill's G92;
/// G98 is 940, feed per minute), kLatheOwnCode + system A's code for the
/// lathe's own. -1 for a code the T series does not have in this system.
int latheCode(char system, int tenths);

/// The name of a lathe function (a latheCode) that mbc does not execute
/// yet, or nullptr.
const char* unmodelledLatheCode(int code);

/// A latheCode as `system` writes it, in tenths; -1 for none.
int systemCode(char system, int code);

/// A latheCode as the profile's G code system writes it: 98 for feed per
/// minute (940) in system A, 94 in B and C; 0 for none.
double writtenLatheCode(const mbrt_ctx& ctx, int code);

/// #4001+g on a lathe: the code of modal group g in the profile's G code
/// system, 0 for groups mbc does not keep.
double latheModalGroupValue(const mbrt_ctx& ctx, int group);

} // namespace mbc::rt
