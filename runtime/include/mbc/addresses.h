// What the FANUC addresses take, for the compile-time checks and the
// runtime alike.
#pragma once

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

/// "O0012", "O80000003": a numbered program's name, at least four digits.
inline std::string programName(int number) {
  const std::string digits = std::to_string(number);
  return "O" + std::string(digits.size() < 4 ? 4 - digits.size() : 0, '0') +
         digits;
}

} // namespace mbc
