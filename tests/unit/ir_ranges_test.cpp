// The range analysis behind mem2ssa's indirection check (ir/passes/ranges.h):
// loop counters get their bounds from the loop condition, conditions narrow
// the blocks they guard (through AND), and what cannot be bounded is every
// number.
#include "ir/passes/ranges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ir_test_support.h"

namespace mbc::ir {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<Range> rangesOf(std::string_view text) {
  Module m = parseText(text);
  return valueRanges(m.functions.at(0));
}

// #1 = 0 / WHILE [#1 LT 3] DO1 / #[#1 + 10] = ... / #1 = #1 + 1 / END1
TEST(IrRanges, LoopCounterIsBoundedByItsCondition) {
  std::vector<Range> r = rangesOf(R"mbir(func @O1 "" {
b0:
  %1 = const 0
  br b1
b1:
  %2 = phi num [%1, b0], [%6, b2]
  %3 = const 3
  %4 = lt %2, %3
  condbr %4, b2, b3
b2:
  %5 = const 10
  %7 = add %2, %5
  stind %7, %2
  %8 = const 1
  %6 = add %2, %8
  br b1
b3:
  ret
}
)mbir");
  // In the body the counter is below 3: at most the double below 3.
  const double below3 = std::nextafter(3.0, 0.0);
  EXPECT_EQ(r[2], (Range{0, below3 + 1})); // 0, and that + 1 after a round
  EXPECT_EQ(r[7], (Range{10, below3 + 10}));
  EXPECT_EQ(r[6], (Range{1, below3 + 1}));
}

TEST(IrRanges, UnknownValuesAndDivisionByAPossibleZero) {
  std::vector<Range> r = rangesOf(R"mbir(func @O1 "" {
b0:
  %1 = ldvar #100
  %2 = tonum %1
  %3 = const 4
  %4 = div %3, %2
  %5 = fn SIN, %2
  %6 = fn ABS, %2
  %7 = vacant
  %8 = tonum %7
  %9 = const -2
  %10 = div %3, %9
  ret
}
)mbir");
  EXPECT_EQ(r[2], (Range{-kInf, kInf}));
  EXPECT_EQ(r[4], (Range{-kInf, kInf}));
  EXPECT_EQ(r[5], (Range{-1, 1}));
  EXPECT_EQ(r[6], (Range{0, kInf}));
  EXPECT_EQ(r[8], (Range{0, 0})); // vacant reads as 0
  EXPECT_LE(r[10].lo, -2);
  EXPECT_GE(r[10].hi, -2);
  EXPECT_LT(r[10].hi - r[10].lo, 1e-6);
}

// IF [[#1 GE 5] AND [#1 LE 8]]: the guarded block sees 5..8; the other
// side of the condition knows nothing (either comparison may be false).
TEST(IrRanges, AndNarrowsTheGuardedBlockOnly) {
  std::vector<Range> r = rangesOf(R"mbir(func @O1 "" {
b0:
  %1 = ldvar #1
  %2 = tonum %1
  %3 = const 5
  %4 = ge %2, %3
  %5 = const 8
  %6 = le %2, %5
  %7 = land %4, %6
  condbr %7, b1, b2
b1:
  %8 = const 100
  %9 = add %2, %8
  br b3
b2:
  %10 = const 100
  %11 = add %2, %10
  br b3
b3:
  ret
}
)mbir");
  EXPECT_EQ(r[9], (Range{105, 108}));
  EXPECT_EQ(r[11], (Range{-kInf, kInf}));
}

// A count that grows without a bound in sight is widened, so the analysis
// ends; the lower bound stays.
TEST(IrRanges, UnboundedLoopIsWidened) {
  std::vector<Range> r = rangesOf(R"mbir(func @O1 "" {
b0:
  %1 = const 1
  br b1
b1:
  %2 = phi num [%1, b0], [%4, b1]
  %3 = const 2
  %4 = mul %2, %3
  %5 = blockskip 1
  condbr %5, b1, b2
b2:
  ret
}
)mbir");
  EXPECT_EQ(r[2], (Range{1, kInf}));
  EXPECT_EQ(r[4], (Range{2, kInf}));
}

RangeFacts factsOf(std::string_view text,
                   const std::vector<std::optional<Range>>& entry) {
  Module m = parseText(text);
  return analyseRanges(m.functions.at(0), entry);
}

// IF [#24 GE 0] ... ELSE N900 with X in 0..20: N900 is never reached, though
// a block no path reaches also jumps there; 10 - #24 spans the zero.
TEST(IrRanges, EntryRangesDecideWhichBlocksRunsReach) {
  const char* text = R"mbir(func @O9040 "" {
b0:
  %1 = ldvar #24
  %5 = const 10
  %2 = tonum %1
  %3 = const 0
  %4 = ge %2, %3
  condbr %4, b1, b2
b1:
  %6 = sub %5, %2
  ret
b2:
  %7 = const 1
  stvar #3000, %7
  ret
b3:
  br b2
}
)mbir";
  std::vector<std::optional<Range>> entry(33, Range{0, 0});
  entry[23] = Range{0, 20};
  RangeFacts facts = factsOf(text, entry);
  EXPECT_EQ(facts.values[6], (Range{-10, 10}));
  EXPECT_TRUE(facts.reachable[1]);
  EXPECT_FALSE(facts.reachable[2]);
  EXPECT_FALSE(facts.reachable[3]);
  // Below zero is possible once the range allows it.
  entry[23] = Range{-1, 20};
  EXPECT_TRUE(factsOf(text, entry).reachable[2]);
  // With nothing known, the load is every number.
  EXPECT_TRUE(factsOf(text, {}).reachable[2]);
}

} // namespace
} // namespace mbc::ir
