// Text inside SVG and HTML elements.
#pragma once

#include <string>
#include <string_view>

namespace mbc::runner {

/// `text` with &, < and > escaped.
inline std::string xmlEscaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    out += c == '&'   ? "&amp;"
           : c == '<' ? "&lt;"
           : c == '>' ? "&gt;"
                      : std::string(1, c);
  }
  return out;
}

} // namespace mbc::runner
