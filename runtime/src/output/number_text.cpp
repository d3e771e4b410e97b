// Numbers as text without the C locale and without a string per number:
// coordinates, which are whole multiples of the least increment, print as
// integer digits; anything else goes through fmt.
#include <mbc/number_text.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>

namespace mbc {

namespace {

/// Whole multiples of 10^-decimals, as every coordinate of a motion is:
/// integer digits, exact, with no formatting of a double; nullptr for
/// any other number.
char* writeIncrements(char* out, double value, int decimals) {
  constexpr int kMaxDecimals = 9;
  static constexpr unsigned long long kPowers[kMaxDecimals + 1] = {
      1,      10,      100,      1000,      10000,
      100000, 1000000, 10000000, 100000000, 1000000000};
  if (decimals < 0 || decimals > kMaxDecimals) {
    return nullptr;
  }
  const double scaled = value * static_cast<double>(kPowers[decimals]);
  const double whole = std::nearbyint(scaled);
  // Near a whole number the correctly rounded decimal is that number; far
  // from one (or too large to count) fmt decides.
  if (!(std::fabs(scaled - whole) < 1e-6) || std::fabs(whole) > 1e15) {
    return nullptr;
  }
  auto units = static_cast<long long>(whole);
  char* end = out;
  if (units < 0) {
    *end++ = '-';
    units = -units;
  }
  const auto magnitude = static_cast<unsigned long long>(units);
  // 16 digits at most: the whole is at most 1e15.
  end = std::to_chars(end, end + 17, magnitude / kPowers[decimals]).ptr;
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
  return end;
}

} // namespace

void appendInteger(std::string& out, long long value) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  out.append(digits, end);
}

char* writeTrimmedFixed(char* out, double value, int decimals) {
  if (char* end = writeIncrements(out, value, decimals)) {
    return end;
  }
  char* end = fmt::format_to(out, "{:.{}f}", value, decimals);
  if (std::find(out, end, '.') != end) {
    while (end[-1] == '0') {
      --end;
    }
    if (end[-1] == '.') {
      --end;
    }
  }
  if (end - out == 2 && out[0] == '-' && out[1] == '0') {
    out[0] = '0';
    --end;
  }
  return end;
}

void appendTrimmedFixed(std::string& out, double value, int decimals) {
  const std::size_t most = trimmedFixedBound(value, decimals);
  char text[64];
  if (most <= sizeof text) {
    out.append(text, writeTrimmedFixed(text, value, decimals));
    return;
  }
  const std::size_t start = out.size();
  out.resize(start + most);
  const char* end = writeTrimmedFixed(out.data() + start, value, decimals);
  out.resize(static_cast<std::size_t>(end - out.data()));
}

std::string trimmedFixed(double value, int decimals) {
  std::string text;
  appendTrimmedFixed(text, value, decimals);
  return text;
}

} // namespace mbc
