// number_text.h: the integer fast path for whole increments gives exactly
// the digits fmt prints for the double.
#include <mbc/number_text.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace mbc {
namespace {

/// The digits fmt gives the double itself, the oracle for the fast path
/// that prints counts of the least increment as integers.
std::string fixedByFmt(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') {
      text.pop_back();
    }
  }
  return text == "-0" ? "0" : text;
}

TEST(NumberText, TrimmedFixedIsTheDigitsOfTheDouble) {
  std::mt19937_64 random(25);
  std::uniform_int_distribution<long long> counts(-2000000000LL, 2000000000LL);
  std::uniform_real_distribution<double> anything(-1e6, 1e6);
  std::uniform_int_distribution<int> decimals(0, 9);
  for (int i = 0; i < 100000; ++i) {
    const int d = decimals(random);
    // A whole number of increments, as every motion holds, and any double,
    // halves of the last digit included.
    const double increments =
        static_cast<double>(counts(random)) / std::pow(10.0, d);
    const double half =
        (static_cast<double>(counts(random)) + 0.5) / std::pow(10.0, d);
    for (const double value : {increments, half, anything(random)}) {
      ASSERT_EQ(trimmedFixed(value, d), fixedByFmt(value, d))
          << fmt::format("{:.17g} with {} decimals", value, d);
    }
  }
  for (const double value :
       {0.0, -0.0, -0.0004, 1e300, -1e20, 0.0005, 1.0005, 2.675, std::nan(""),
        std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(trimmedFixed(value, 3), fixedByFmt(value, 3)) << value;
  }
}

TEST(NumberText, Integers) {
  std::string out = "N";
  appendInteger(out, 0);
  appendInteger(out, -42);
  appendInteger(out, std::numeric_limits<long long>::min());
  EXPECT_EQ(out, "N0-42-9223372036854775808");
}

} // namespace
} // namespace mbc
