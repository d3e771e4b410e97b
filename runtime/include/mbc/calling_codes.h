// Which NC words may call a macro or subprogram instead of acting as
// themselves. One rule for the runtime (which makes the calls), the machine
// profile's check (which refuses a parameter the rule does not allow) and
// the IR passes (which keep locals in memory across a block that may call,
// for any profile, since code is compiled before the profile is known).
#pragma once

namespace mbc {

/// The parameters that make codes call (spec §5.7): 6050-6059 give custom
/// G codes for O9010-O9019 (negative: modal, like G66), 6071-6079 M codes
/// for subprograms O9001-O9009, 6080-6089 M codes for macros O9020-O9029.
struct CodeTable {
  int firstParameter;
  int size;
  int firstProgram;
};

inline constexpr CodeTable kCustomGCodes{6050, 10, 9010};
inline constexpr CodeTable kSubprogramMCodes{6071, 9, 9001};
inline constexpr CodeTable kMacroMCodes{6080, 10, 9020};

inline constexpr bool isCallingCodeParameter(int n) {
  return n >= kCustomGCodes.firstParameter &&
         n < kMacroMCodes.firstParameter + kMacroMCodes.size;
}

/// Whether G<tenths/10> may be made a custom macro code: FANUC's own G
/// codes that mbc executes never are (G65, G66 and G66.1 call by
/// themselves); one it does not execute may be.
bool mayBeCustomGCode(int tenths);

/// Whether a profile may make M<m> call: not M00, M01, M02, M30 (they stop
/// or end the program) nor M98, M99, M198 (they call or return already).
bool mayBeCustomMCode(double m);

/// Whether a G word may call on some machine: a custom code, or with
/// `modalCalls` G66 and G66.1 (which call at later blocks).
bool gCodeMayCall(int tenths, bool modalCalls);

/// Whether an M word may call or return on some machine: every M code but
/// the ones that stop or end the program.
bool mCodeMayCall(double m);

/// M98 and M198: the subprogram calls whose P names the program (spec
/// §5.1; M198 from the external device).
inline constexpr bool isSubprogramCall(char letter, double value) {
  return letter == 'M' && (value == 98 || value == 198);
}

/// G65, G66 and G66.1: the macro calls whose P names the program.
inline constexpr bool isMacroCall(char letter, double value) {
  return letter == 'G' && (value == 65 || value == 66 || value == 66.1);
}

/// The codes whose P (or a program name in its place) names the program
/// they call.
inline constexpr bool callsByP(char letter, double value) {
  return isSubprogramCall(letter, value) || isMacroCall(letter, value);
}

/// T, S and B call O9000, O9029, O9028 when a profile says so (6001#5,
/// 6007#5, 6007#4).
inline constexpr bool letterMayCall(char letter) {
  return letter == 'T' || letter == 'S' || letter == 'B';
}

/// The subprograms T, S and B codes call.
inline constexpr int kTCodeProgram = 9000;
inline constexpr int kSCodeProgram = 9029;
inline constexpr int kBCodeProgram = 9028;

/// Whether some code may call program `number` on some machine, with
/// words a check of the program text does not see as a call: O9000-O9029.
inline constexpr bool codeMayCallProgram(int number) {
  return number >= kTCodeProgram &&
         number < kMacroMCodes.firstProgram + kMacroMCodes.size;
}

/// Whether a code may call program `number` as a subprogram, on the
/// caller's locals: O9000 (T), O9001-O9009 (M), O9028 (B), O9029 (S).
inline constexpr bool codeMayCallSubprogram(int number) {
  return number == kTCodeProgram || number == kSCodeProgram ||
         number == kBCodeProgram ||
         (number >= kSubprogramMCodes.firstProgram &&
          number < kSubprogramMCodes.firstProgram + kSubprogramMCodes.size);
}

} // namespace mbc
