// What the FANUC addresses take, for the compile-time checks and the
// runtime alike.
#pragma once

#include <string_view>

namespace mbc {

/// M S T H D take whole numbers: no decimal point, no sign.
inline bool isWholeNumberAddress(char letter) {
  return std::string_view("DHMST").find(letter) != std::string_view::npos;
}

} // namespace mbc
