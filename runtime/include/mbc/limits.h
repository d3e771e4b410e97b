// The numbers of the Macro B language: which variables exist everywhere,
// sequence and program numbers, loops. One header for the frontend, the IR
// passes, codegen, the runtime and the driver (spec §1.3, §1.4, §2, §4).
// What a machine profile changes (extended commons, nesting depths) the
// runtime reads from the profile; these are the fixed parts and the
// profile's bounds.
#pragma once

#include <cstdint>
#include <limits>

namespace mbc {

// === Variables (spec §2) ===
/// #1-#33: a call level's locals.
inline constexpr int kFirstLocal = 1;
inline constexpr int kLastLocal = 33;
inline constexpr int kLocalCount = kLastLocal - kFirstLocal + 1;
/// #100-#199 (cleared at power-off) and #500-#999 (kept): the commons every
/// machine has.
inline constexpr int kFirstCommon = 100;
inline constexpr int kLastCommon = 199;
inline constexpr int kFirstNonvolatile = 500;
inline constexpr int kLastNonvolatile = 999;
/// The commons a machine profile may add ("extended_common").
inline constexpr int kFirstExtendedCommon = 200;
inline constexpr int kLastExtendedCommon = 499;
/// The additional commons of a 30i-B option ("common_98000").
inline constexpr int kFirstCommon98000 = 98000;
inline constexpr int kLastCommon98000 = 98499;
/// #3000 = n: the macro alarm, which ends the run at its block.
inline constexpr int kMacroAlarmVariable = 3000;
/// The largest n of #3000 = n: the alarm shown is 3000 + n.
inline constexpr int kMacroAlarmLast = 999;
/// A #[n] with |n| at least this is no variable at all (PS0115).
inline constexpr double kBeyondAnyVariable = 1e9;

inline constexpr bool isLocal(std::int64_t n) {
  return n >= kFirstLocal && n <= kLastLocal;
}

/// #100-#199 and #500-#999.
inline constexpr bool isFixedCommon(std::int64_t n) {
  return (n >= kFirstCommon && n <= kLastCommon) ||
         (n >= kFirstNonvolatile && n <= kLastNonvolatile);
}

// === Sequence numbers (spec §1.4) ===
/// N1-N99999, the targets of GOTO and M99 P.
inline constexpr int kMaxSequenceNumber = 99'999;

/// Whether a rounded jump target is a sequence number.
inline constexpr bool isSequenceNumber(double n) {
  return n >= 1 && n <= kMaxSequenceNumber;
}

// === Loops (spec §4) ===
/// DO1-DO3, nested at most three deep.
inline constexpr int kMaxLoopNumber = 3;
inline constexpr int kMaxLoopNesting = 3;

// === Programs (spec §1.3) ===
/// Program numbers O1-O99999999: the 8-digit program number option, common
/// on 0i-F and 30i-B; a machine profile can keep the standard O1-O9999.
inline constexpr int kMaxProgramNumber = 99'999'999;
inline constexpr int kMaxProgramNumber4Digits = 9'999;

/// Programs called by name (`M98 <DRILL>`, `G65 <BOLT>`) get numbers above
/// every O number, so that each engine finds them by number as it finds O
/// numbers. No packed M98 P of a 4-digit control reaches them (its largest
/// is 9999 repeats of O9999).
inline constexpr int kFirstNamedProgram = 100'000'000;

/// The largest number a call looks up (rounded P); above it, PS0076.
inline constexpr int kMaxCallNumber = std::numeric_limits<int>::max();

inline constexpr bool isNamedProgramNumber(double number) {
  return number >= kFirstNamedProgram;
}

} // namespace mbc
