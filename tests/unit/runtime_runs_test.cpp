// One run after another in a context: what a new run keeps of the machine
// (as a control after RESET) and what the reset calls put back.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kClearOnReset = R"({"parameters": {"3402": 64}})";

/// A first run that leaves the tool at X10 in G91 G01 with F, S and M set,
/// then the start of the second.
void runThenStartAnother(Machine& m) {
  ASSERT_EQ(m.block("G91 G01 X10. F250 S1200 M03"), 0);
  mbrt_start(m.ctx(), "O1001");
}

void expectVariables(Machine& m,
                     std::initializer_list<std::pair<int, double>> expected) {
  for (const auto& [number, value] : expected) {
    EXPECT_EQ(m.read(number), value) << '#' << number;
  }
}

// The reset state: modal codes and the last words (#4101+) stay.
TEST(RuntimeRuns, ARunGoesOnFromWhereTheLastLeftTheTool) {
  Machine m;
  runThenStartAnother(m);
  expectVariables(
      m, {{4003, 91}, {4001, 1}, {4109, 250}, {4119, 1200}, {4113, 3}});
  ASSERT_EQ(m.block("X5."), 0);
  ASSERT_EQ(m.motions().size(), 2U);
  EXPECT_EQ(m.motions()[1].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[1].start[0], 10.0);
  EXPECT_EQ(m.motions()[1].end[0], 15.0);
  EXPECT_STREQ(m.motions()[1].program, "O1001");
}

// 3402#6 CLR, the clear state: power-on codes, no last words; the tool
// stays where it is.
TEST(RuntimeRuns, ClearStateTakesThePowerOnCodesButNotThePosition) {
  Machine m(kClearOnReset);
  runThenStartAnother(m);
  expectVariables(
      m, {{4003, 90}, {4001, 0}, {4109, 0}, {4119, 0}, {4113, 0}, {5001, 10}});
  ASSERT_EQ(m.block("X4."), 0);
  EXPECT_EQ(m.motions().back().kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions().back().start[0], 10.0);
  EXPECT_EQ(m.motions().back().end[0], 4.0);
}

TEST(RuntimeRuns, ANewRunCancelsWhatResetCancels) {
  Machine m;
  ASSERT_EQ(m.block("G90 G00 Z10."), 0);
  ASSERT_EQ(m.block("G81 X1. Y1. Z-2. R1. F100"), 0);
  ASSERT_EQ(m.write(3004, 7), 0);
  const size_t holeMoves = m.motions().size();
  mbrt_start(m.ctx(), "O1000");
  EXPECT_EQ(m.read(4009), 80.0);
  EXPECT_EQ(m.read(3004), 0.0);
  ASSERT_EQ(m.block("X5."), 0); // a rapid, not another hole
  ASSERT_EQ(m.motions().size(), holeMoves + 1);
  EXPECT_EQ(m.motions().back().kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions().back().cycle, 0);
}

TEST(RuntimeRuns, ResetStateHomesTheMachineAndKeepsItsData) {
  Machine m;
  ASSERT_EQ(m.write(500, 7), 0);
  ASSERT_EQ(m.block("G91 G01 X10. Y3. F100"), 0);
  ASSERT_EQ(m.block("G92 X0 Y0"), 0);
  mbrt_reset_state(m.ctx());
  EXPECT_EQ(m.read(4003), 90.0);
  EXPECT_EQ(m.read(5021), 0.0);
  EXPECT_EQ(m.read(5001), 0.0);
  EXPECT_EQ(m.read(500), 7.0);
  ASSERT_EQ(m.block("X4."), 0);
  EXPECT_EQ(m.motions().back().start[0], 0.0);
  EXPECT_EQ(m.motions().back().end[0], 4.0);
  mbrt_reset(m.ctx());
  EXPECT_TRUE(isVacant(m.read(500)));
}

} // namespace
} // namespace mbc::test
