// Numbers as the output files print them: the same digits on every
// machine, whatever the C locale, appended without a string per number.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

namespace mbc {

/// `value` fixed with `decimals` digits, then trailing zeros and '.'
/// dropped; "-0" becomes "0".
std::string trimmedFixed(double value, int decimals);

/// trimmedFixed appended to `out`.
void appendTrimmedFixed(std::string& out, double value, int decimals);

/// The most characters trimmedFixed writes for `value`: the sign, 16
/// digits, the point and the decimals up to 1e15; every digit of a double
/// beyond. Inline: a writer thread counts it for every number of every
/// record on the run's thread.
inline std::size_t trimmedFixedBound(double value, int decimals) {
  constexpr std::size_t kLargestDouble = 309; // digits of DBL_MAX
  // Up to 1e15 a number has at most 16 digits before the point, as
  // increments or through fmt; beyond, fmt writes all of them.
  const std::size_t places =
      decimals > 0 ? static_cast<std::size_t>(decimals) : 0;
  const bool counted = std::fabs(value) <= 1e15;
  return (counted ? 17 : kLargestDouble + 1) + 1 + places;
}

/// trimmedFixed written at `out`, which has room for trimmedFixedBound
/// characters; the end of what it wrote.
char* writeTrimmedFixed(char* out, double value, int decimals);

/// The decimal digits of `value`, with '-' when negative.
void appendInteger(std::string& out, long long value);

} // namespace mbc
