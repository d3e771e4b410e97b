// UTF-8 in source text: what diagnostics may print as it is and what they
// must escape (invalid bytes would garble a terminal).
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace mbc {

inline bool isContinuation(unsigned char c) {
  return (c & 0xC0) == 0x80;
}

/// Length of the valid UTF-8 sequence at text[i], or 0.
inline std::size_t utf8Length(std::string_view text, std::size_t i) {
  auto b = static_cast<unsigned char>(text[i]);
  std::size_t n = b >= 0xF0 && b <= 0xF4 ? 4
                  : b >= 0xE0            ? 3
                  : b >= 0xC2            ? 2
                                         : 0;
  if (n == 0 || i + n > text.size()) {
    return 0;
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (!isContinuation(static_cast<unsigned char>(text[i + k]))) {
      return 0;
    }
  }
  return n;
}

/// Printable ASCII and one valid UTF-8 character as they are; anything
/// else as \xNN per byte.
inline std::string shownCharacter(std::string_view bytes) {
  const auto first = static_cast<unsigned char>(bytes.empty() ? 0 : bytes[0]);
  const bool printable = bytes.size() == 1
                             ? first >= 0x20 && first < 0x7F
                             : utf8Length(bytes, 0) == bytes.size();
  if (printable) {
    return std::string(bytes);
  }
  std::string shown;
  for (char c : bytes) {
    shown += fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
  }
  return shown;
}

} // namespace mbc
