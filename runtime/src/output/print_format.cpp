// DPRNT and BPRNT formatting (spec §7.3, §7.4). Rounding is done on decimal
// digit strings so that what is printed matches the number the program
// wrote (2.675 rounds to 2.68), not its binary approximation.
#include "print_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

namespace mbc::rt {

namespace {

/// Format digits are single decimal digits in the program text; anything
/// else is clamped rather than trusted.
int clampDigits(int digits) {
  return std::clamp(digits, 0, 9);
}

/// A magnitude split into decimal digit strings; `whole` has no leading
/// zeros (empty for zero) and `fraction` exactly the requested length.
struct Decimal {
  std::string whole;
  std::string fraction;

  bool isZero() const {
    return whole.empty() &&
           fraction.find_first_not_of('0') == std::string::npos;
  }
};

/// Adds one unit in the last place of `digits` (a non-empty digit string),
/// growing it when the carry runs off the front.
void incrementDigits(std::string& digits) {
  for (auto it = digits.rbegin(); it != digits.rend(); ++it) {
    if (*it != '9') {
      ++*it;
      return;
    }
    *it = '0';
  }
  digits.insert(digits.begin(), '1');
}

/// The shortest decimal text that reads back as `magnitude`, in fixed
/// notation (never exponent form).
std::string shortestFixed(double magnitude) {
  // 5e-324 in fixed notation needs 327 characters; 1.8e308 needs 309.
  char buffer[400];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, magnitude,
                                    std::chars_format::fixed);
  return std::string(buffer, result.ptr);
}

/// |value| rounded half away from zero to `fracDigits` decimals.
Decimal roundedMagnitude(double value, int fracDigits) {
  const double magnitude = std::isfinite(value) ? std::fabs(value) : 0.0;
  const std::string text = shortestFixed(magnitude);
  const auto dot = text.find('.');
  std::string whole = text.substr(0, dot);
  std::string fraction = dot == std::string::npos ? "" : text.substr(dot + 1);
  const auto keep = static_cast<std::size_t>(fracDigits);
  const bool roundUp = fraction.size() > keep && fraction[keep] >= '5';
  fraction.resize(keep, '0');

  std::string digits = whole + fraction;
  if (roundUp) {
    incrementDigits(digits);
  }
  const std::size_t wholeLength = digits.size() - keep;
  Decimal rounded{digits.substr(0, wholeLength), digits.substr(wholeLength)};
  rounded.whole.erase(0, rounded.whole.find_first_not_of('0'));
  return rounded;
}

/// The c low-order integer digits with leading zeros blanked (PRT = 0) or
/// dropped (PRT = 1); the units digit always shows.
std::string integerField(const std::string& whole, int intDigits, bool prt) {
  const auto width = static_cast<std::size_t>(intDigits);
  std::string field = whole.size() >= width
                          ? whole.substr(whole.size() - width)
                          : std::string(width - whole.size(), '0') + whole;
  std::size_t leading = 0;
  while (leading + 1 < field.size() && field[leading] == '0') {
    ++leading;
  }
  if (prt) {
    return field.substr(leading);
  }
  return std::string(leading, ' ') + field.substr(leading);
}

} // namespace

std::string formatDprntValue(Num value, int intDigits, int fracDigits,
                             bool prt) {
  intDigits = clampDigits(intDigits);
  fracDigits = clampDigits(fracDigits);
  const double number = numeric(value);
  const Decimal rounded = roundedMagnitude(number, fracDigits);

  std::string text;
  if (number < 0.0 && !rounded.isZero()) {
    text += '-';
  } else if (!prt) {
    text += ' ';
  }
  text += integerField(rounded.whole, intDigits, prt);
  if (fracDigits > 0) {
    text += '.';
    text += rounded.fraction;
  }
  return text;
}

std::string formatPrintText(const char* text) {
  std::string printed = text ? text : "";
  std::replace(printed.begin(), printed.end(), '*', ' ');
  return printed;
}

bool appendBprntValue(std::string& out, Num value, int fracDigits) {
  const double number = numeric(value);
  const Decimal rounded = roundedMagnitude(number, clampDigits(fracDigits));
  std::string digits = rounded.whole + rounded.fraction;
  digits.erase(0, digits.find_first_not_of('0'));
  // Ten digits exceed any int32; the check below handles the rest exactly.
  if (digits.size() > 10) {
    return false;
  }
  std::int64_t scaled = 0;
  for (char digit : digits) {
    scaled = scaled * 10 + (digit - '0');
  }
  if (number < 0.0) {
    scaled = -scaled;
  }
  if (scaled < std::numeric_limits<std::int32_t>::min() ||
      scaled > std::numeric_limits<std::int32_t>::max()) {
    return false;
  }
  const auto word = static_cast<std::uint32_t>(scaled);
  for (int shift = 24; shift >= 0; shift -= 8) {
    out += static_cast<char>((word >> shift) & 0xFF);
  }
  return true;
}

} // namespace mbc::rt
