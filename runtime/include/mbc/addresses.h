// What the FANUC addresses take, for the compile-time checks and the
// runtime alike.
#pragma once

#include <limits>
#include <string>
#include <string_view>

namespace mbc {

/// M S T H D take whole numbers: no decimal point, no sign.
inline bool isWholeNumberAddress(char letter) {
  return std::string_view("DHMST").find(letter) != std::string_view::npos;
}

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

inline bool isNamedProgramNumber(double number) {
  return number >= kFirstNamedProgram;
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
