// Unit tests of DPRNT/BPRNT formatting (print_format.h, spec §7.3, §7.4),
// including the worked examples of the spec.
#include "runtime/src/output/print_format.h"

#include <gtest/gtest.h>

#include <string>

namespace mbc::rt {
namespace {

std::string bprnt(Num value, int fracDigits) {
  std::string out;
  EXPECT_TRUE(appendBprntValue(out, value, fracDigits));
  return out;
}

std::string bytes(std::initializer_list<unsigned char> list) {
  return std::string(list.begin(), list.end());
}

TEST(Dprnt, SpecExamplePrtZero) {
  EXPECT_EQ(formatDprntValue(128.47398, 5, 3, false), "   128.474");
  EXPECT_EQ(formatDprntValue(-91.2, 5, 3, false), "-   91.200");
  EXPECT_EQ(formatDprntValue(123.456, 2, 0, false), " 23");
}

TEST(Dprnt, SpecExamplePrtOne) {
  EXPECT_EQ(formatDprntValue(128.47398, 5, 3, true), "128.474");
  EXPECT_EQ(formatDprntValue(-91.2, 5, 3, true), "-91.200");
  EXPECT_EQ(formatDprntValue(123.456, 2, 0, true), "23");
}

TEST(Dprnt, SevenPointFive) {
  EXPECT_EQ(formatDprntValue(7.5, 3, 3, false), "   7.500");
  EXPECT_EQ(formatDprntValue(7.5, 3, 3, true), "7.500");
  EXPECT_EQ(formatDprntValue(7.5, 2, 0, false), "  8");
  EXPECT_EQ(formatDprntValue(-7.5, 2, 0, false), "- 8");
}

TEST(Dprnt, RoundsTheDecimalText) {
  EXPECT_EQ(formatDprntValue(2.675, 1, 2, true), "2.68");
  EXPECT_EQ(formatDprntValue(1.005, 1, 2, true), "1.01");
  EXPECT_EQ(formatDprntValue(0.125, 1, 2, true), "0.13");
  EXPECT_EQ(formatDprntValue(2.674999, 1, 2, true), "2.67");
  EXPECT_EQ(formatDprntValue(9.9996, 2, 3, false), " 10.000");
  EXPECT_EQ(formatDprntValue(99.96, 2, 1, true), "0.0");
}

TEST(Dprnt, UnitsDigitAlwaysPrinted) {
  EXPECT_EQ(formatDprntValue(0.5, 3, 3, false), "   0.500");
  EXPECT_EQ(formatDprntValue(0.5, 3, 3, true), "0.500");
  EXPECT_EQ(formatDprntValue(0.0, 3, 0, false), "   0");
  EXPECT_EQ(formatDprntValue(-0.25, 1, 2, false), "-0.25");
  EXPECT_EQ(formatDprntValue(1000.0, 2, 0, false), "  0");
}

TEST(Dprnt, NoIntegerDigits) {
  EXPECT_EQ(formatDprntValue(0.5, 0, 3, false), " .500");
  EXPECT_EQ(formatDprntValue(12.5, 0, 1, true), ".5");
  EXPECT_EQ(formatDprntValue(-0.5, 0, 2, true), "-.50");
}

TEST(Dprnt, ZeroIsNeverNegative) {
  EXPECT_EQ(formatDprntValue(-0.0001, 1, 3, false), " 0.000");
  EXPECT_EQ(formatDprntValue(-0.0001, 1, 3, true), "0.000");
  EXPECT_EQ(formatDprntValue(-0.0, 1, 0, true), "0");
  EXPECT_EQ(formatDprntValue(-0.0005, 1, 3, true), "-0.001");
}

TEST(Dprnt, VacantPrintsAsZero) {
  EXPECT_EQ(formatDprntValue(vacant(), 3, 2, false), "   0.00");
  EXPECT_EQ(formatDprntValue(vacant(), 3, 2, true), "0.00");
}

TEST(Dprnt, ClampsDigitCounts) {
  EXPECT_EQ(formatDprntValue(1.5, -1, 12, true), ".500000000");
  EXPECT_EQ(formatDprntValue(1234567890123.0, 12, 0, true), "567890123");
}

TEST(Dprnt, LargeAndTinyMagnitudes) {
  EXPECT_EQ(formatDprntValue(1e20, 3, 1, false), "   0.0");
  EXPECT_EQ(formatDprntValue(1.5e-10, 2, 3, true), "0.000");
  EXPECT_EQ(formatDprntValue(987654321.0, 9, 0, true), "987654321");
}

TEST(PrintText, StarBecomesSpace) {
  EXPECT_EQ(formatPrintText("DIA*"), "DIA ");
  EXPECT_EQ(formatPrintText("**X*Y"), "  X Y");
  EXPECT_EQ(formatPrintText(""), "");
}

TEST(Bprnt, SpecExamples) {
  EXPECT_EQ(bprnt(0.25, 3), bytes({0x00, 0x00, 0x00, 0xFA}));
  EXPECT_EQ(bprnt(-3.5, 2), bytes({0xFF, 0xFF, 0xFE, 0xA2}));
  EXPECT_EQ(bprnt(12.34, 0), bytes({0x00, 0x00, 0x00, 0x0C}));
}

TEST(Bprnt, AppendsAfterExistingText) {
  std::string out = "A";
  EXPECT_TRUE(appendBprntValue(out, 1.0, 0));
  EXPECT_EQ(out, std::string("A") + bytes({0x00, 0x00, 0x00, 0x01}));
}

TEST(Bprnt, RoundingAndVacant) {
  EXPECT_EQ(bprnt(vacant(), 3), bytes({0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(bprnt(2.5, 0), bytes({0x00, 0x00, 0x00, 0x03}));
  EXPECT_EQ(bprnt(-2.5, 0), bytes({0xFF, 0xFF, 0xFF, 0xFD}));
  EXPECT_EQ(bprnt(-0.0001, 2), bytes({0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(bprnt(-1.0, 0), bytes({0xFF, 0xFF, 0xFF, 0xFF}));
}

TEST(Bprnt, Int32Limits) {
  EXPECT_EQ(bprnt(2147483647.0, 0), bytes({0x7F, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(bprnt(-2147483648.0, 0), bytes({0x80, 0x00, 0x00, 0x00}));
  EXPECT_EQ(bprnt(2147483.647, 3), bytes({0x7F, 0xFF, 0xFF, 0xFF}));
}

TEST(Bprnt, RejectsValuesOutsideInt32) {
  std::string out = "keep";
  EXPECT_FALSE(appendBprntValue(out, 2147483648.0, 0));
  EXPECT_FALSE(appendBprntValue(out, -2147483649.0, 0));
  EXPECT_FALSE(appendBprntValue(out, 2147483.6475, 3));
  EXPECT_FALSE(appendBprntValue(out, 1e30, 0));
  EXPECT_EQ(out, "keep");
}

} // namespace
} // namespace mbc::rt
