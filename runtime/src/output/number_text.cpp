// Numbers as text without the C locale and without a string per number:
// coordinates, which are whole multiples of the least increment, print as
// integer digits; anything else goes through fmt.
#include <mbc/number_text.h>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <iterator>

namespace mbc {

namespace {

/// Whole multiples of 10^-decimals, as every coordinate of a motion is:
/// integer digits, exact, with no formatting of a double.
bool appendIncrements(std::string& out, double value, int decimals) {
  constexpr int kMaxDecimals = 9;
  static constexpr unsigned long long kPowers[kMaxDecimals + 1] = {
      1,      10,      100,      1000,      10000,
      100000, 1000000, 10000000, 100000000, 1000000000};
  if (decimals < 0 || decimals > kMaxDecimals) {
    return false;
  }
  const double scaled = value * static_cast<double>(kPowers[decimals]);
  const double whole = std::nearbyint(scaled);
  // Near a whole number the correctly rounded decimal is that number; far
  // from one (or too large to count) fmt decides.
  if (!(std::fabs(scaled - whole) < 1e-6) || std::fabs(whole) > 1e15) {
    return false;
  }
  auto units = static_cast<long long>(whole);
  // Sign, 16 digits and the point at most: built here, appended once.
  char text[24];
  char* end = text;
  if (units < 0) {
    *end++ = '-';
    units = -units;
  }
  const auto magnitude = static_cast<unsigned long long>(units);
  end =
      std::to_chars(end, text + sizeof text, magnitude / kPowers[decimals]).ptr;
  unsigned long long fraction = magnitude % kPowers[decimals];
  if (fraction != 0) {
    int digits = decimals;
    while (fraction % 10 == 0) {
      fraction /= 10;
      --digits;
    }
    *end++ = '.';
    for (int i = digits - 1; i >= 0; --i) {
      end[i] = static_cast<char>('0' + fraction % 10);
      fraction /= 10;
    }
    end += digits;
  }
  out.append(text, end);
  return true;
}

} // namespace

void appendInteger(std::string& out, long long value) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  out.append(digits, end);
}

void appendTrimmedFixed(std::string& out, double value, int decimals) {
  if (appendIncrements(out, value, decimals)) {
    return;
  }
  const std::size_t start = out.size();
  fmt::format_to(std::back_inserter(out), "{:.{}f}", value, decimals);
  if (out.find('.', start) != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') {
      out.pop_back();
    }
  }
  if (out.compare(start, std::string::npos, "-0") == 0) {
    out.replace(start, std::string::npos, "0");
  }
}

std::string trimmedFixed(double value, int decimals) {
  std::string text;
  appendTrimmedFixed(text, value, decimals);
  return text;
}

} // namespace mbc
