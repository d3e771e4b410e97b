// What the FANUC addresses take, for the compile-time checks and the
// runtime alike.
#pragma once

#include <mbc/arith.h>
#include <mbc/limits.h>

#include <optional>
#include <string>
#include <string_view>

namespace mbc {

/// M S T H D take whole numbers: no decimal point, no sign.
inline bool isWholeNumberAddress(char letter) {
  return std::string_view("DHMST").find(letter) != std::string_view::npos;
}

/// I J K and R: an arc's centre or radius (a length in input units).
constexpr bool isArcCenterLetter(char letter) {
  return letter == 'I' || letter == 'J' || letter == 'K' || letter == 'R';
}

/// ,C ,R and ,A (chamfer, corner R, angle of a line) travel from the parser
/// to the runtime as the lower-case letter: every table of the addresses
/// A..Z passes them by, and no upper-case letter is mistaken for them.
constexpr char commaWordLetter(char address) {
  return static_cast<char>(address - 'A' + 'a');
}

constexpr bool isCommaWord(char letter) {
  return letter == 'a' || letter == 'c' || letter == 'r';
}

/// The letter after the comma of a comma word: 'C' for ,C.
constexpr char commaWordAddress(char letter) {
  return static_cast<char>(letter - 'a' + 'A');
}

/// Appends "X", or ",C" for a comma word: an address as the program
/// writes it.
inline void appendAddressText(std::string& out, char letter) {
  if (isCommaWord(letter)) {
    out += ',';
    out += commaWordAddress(letter);
    return;
  }
  out += letter;
}

inline std::string addressText(char letter) {
  std::string text;
  appendAddressText(text, letter);
  return text;
}

/// Specification I (spec §5.2): the local variable a G65 argument letter
/// sets, 0 for the letters that cannot be arguments (G, L, N, O, P).
constexpr int argumentLocal(char letter) {
  constexpr int kLocal[26] = {
      1, 2, 3, 7,  8,  9,  0,  11, 4,  5,  6,  0,  13, // A..M
      0, 0, 0, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, // N..Z
  };
  return letter >= 'A' && letter <= 'Z' ? kLocal[letter - 'A'] : 0;
}

/// The letter of specification I that sets local #n, or 0 for a local no
/// letter sets.
constexpr char argumentLetter(int n) {
  for (char letter = 'A'; letter <= 'Z' && n != 0; ++letter) {
    if (argumentLocal(letter) == n) {
      return letter;
    }
  }
  return 0;
}

inline constexpr int kMaxIjkSets = 10;

/// Specification II (spec §5.3): the locals of the I, J, K arguments of one
/// call, word by word. A repeated letter, or one out of I-J-K order, starts
/// the next set.
struct IjkSets {
  int set = 0;
  int last = -1;

  /// The local for I (0), J (1) or K (2); 0 beyond ten sets.
  constexpr int next(int member) {
    if (set == 0 || member <= last) {
      ++set;
    }
    last = member;
    return set > kMaxIjkSets ? 0 : 4 + 3 * (set - 1) + member;
  }
};

/// The local the next argument word of a call sets: I, J and K by the
/// sets of specification II, the other letters by specification I; 0 for
/// a letter that is no argument or an eleventh set.
constexpr int nextArgumentLocal(char letter, IjkSets& sets) {
  return letter >= 'I' && letter <= 'K' ? sets.next(letter - 'I')
                                        : argumentLocal(letter);
}

/// The program number a call's P names, rounded half away from zero as the
/// control rounds addresses; none when no program can have it (PS0076).
inline std::optional<int> calledProgramNumber(double p) {
  const double n = roundHalfAway(p);
  if (!(n >= 0 && n <= kMaxCallNumber)) {
    return std::nullopt;
  }
  return static_cast<int>(n);
}

/// "O0012", "O80000003": a numbered program's name, at least four digits.
inline std::string programName(int number) {
  const std::string digits = std::to_string(number);
  return "O" + std::string(digits.size() < 4 ? 4 - digits.size() : 0, '0') +
         digits;
}

/// Whether `wanted` (from --main) names the program `name` numbered
/// `number`: "O12", "o0012" and "O0012" name O0012; "drill", "DRILL" and
/// "<DRILL>" name <DRILL> (the parser writes names in upper case).
inline bool namesProgram(std::string_view name, int number,
                         std::string_view wanted) {
  if (wanted.empty()) {
    return false;
  }
  if ((wanted[0] == 'O' || wanted[0] == 'o') && number >= 0 &&
      number < kFirstNamedProgram && wanted.size() > 1 && wanted.size() < 11 &&
      wanted.find_first_not_of("0123456789", 1) == std::string_view::npos) {
    return std::stol(std::string(wanted.substr(1))) == number;
  }
  std::string upper = wanted.starts_with('<') ? "" : "<";
  for (const char c : wanted) {
    upper += c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
  }
  upper += wanted.ends_with('>') ? "" : ">";
  return name == upper || name == wanted;
}

} // namespace mbc
