// Canned cycles (runtime/src/machine/canned_cycles.cpp): the moves of one hole,
// the modal drilling data and the alarms.
#include "runtime_test_support.h"

namespace mbc::test {

TEST(RuntimeCannedCycles, G81HoleMovesAndReturnLevels) {
  Machine m;
  ASSERT_EQ(m.block("G00 Z20."), 0);
  ASSERT_EQ(m.block("G99 G81 X5. Z-3. R1. F60."), 0);
  ASSERT_EQ(m.json().size(), 5u);
  EXPECT_EQ(m.json()[1],
            "{\"motion\":\"rapid\",\"x\":5,\"y\":0,\"z\":20,\"mx\":5,\"my\":0,"
            "\"mz\":20,\"cycle\":\"G81\",\"line\":1,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(
      m.json()[3],
      "{\"motion\":\"linear\",\"x\":5,\"y\":0,\"z\":-3,\"mx\":5,\"my\":0,"
      "\"mz\":-3,\"f\":60,\"cycle\":\"G81\",\"line\":1,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(m.read(5003), 1.0); // G99: at R
  ASSERT_EQ(m.block("G98 X6."), 0);
  EXPECT_EQ(m.read(5003), 20.0); // G98: the initial level
  ASSERT_EQ(m.block("G80"), 0);
  EXPECT_EQ(m.read(4009), 80.0);
}

TEST(RuntimeCannedCycles, BlocksWithoutAxisWordsOnlyKeepData) {
  Machine m;
  ASSERT_EQ(m.block("G81 Z-3. F60."), 0); // Z is an axis word: drills here
  const size_t moves = m.motions().size();
  ASSERT_EQ(m.block("F80. Q1."), 0);
  EXPECT_EQ(m.motions().size(), moves);
  ASSERT_EQ(m.block("X1. K0"), 0);
  EXPECT_EQ(m.motions().size(), moves);
}

TEST(RuntimeCannedCycles, GroupOneCodesCancelTheCycleAndItsData) {
  Machine m;
  ASSERT_EQ(m.block("G81 X1. Z-3. R1. F60."), 0);
  ASSERT_EQ(m.block("G01 X2."), 0);
  EXPECT_EQ(m.read(4009), 80.0);
  EXPECT_EQ(m.block("G81 X3.", 4), status(AlarmId::ImproperNcAddress));
  EXPECT_EQ(m.report(), "test.nc:4: alarm PS0009: IMPROPER NC-ADDRESS: G81 "
                        "without Z (the hole bottom)\n");
}

TEST(RuntimeCannedCycles, PeckDrillingRetractsByTheParameter) {
  Machine m(R"({"parameters": {"5114": 0.5}})");
  ASSERT_EQ(m.block("G73 Z-3. R0 Q1. F60."), 0);
  std::vector<double> z;
  for (const mbrt_motion& motion : m.motions()) {
    z.push_back(motion.end[2]);
  }
  EXPECT_EQ(z, (std::vector<double>{-1, -0.5, -2, -1.5, -3, 0}));
}

TEST(RuntimeCannedCycles, FeedZeroAndBadRepeat) {
  Machine m;
  EXPECT_EQ(m.block("G81 X1. Z-1. R1."), status(AlarmId::FeedZero));
  Machine n;
  EXPECT_EQ(n.block("G81 X1. Z-1. R1. F10. K10000"),
            status(AlarmId::ImproperNcAddress));
}

TEST(RuntimeCannedCycles, DwellAdvancesTheClock) {
  Machine m;
  ASSERT_EQ(m.block("G04 P1500"), 0);
  ASSERT_EQ(m.block("G04 X2."), 0);
  ASSERT_EQ(m.block("G04 X250"), 0);
  EXPECT_EQ(m.read(3001), 3750.0);
  EXPECT_TRUE(m.motions().empty());
}

// G73 and G83 need the depth of each peck (FANUC PS0045), alarmed before
// the cycle moves.
TEST(RuntimeCannedCycles, PeckWithoutQAlarms) {
  Machine m;
  EXPECT_EQ(m.block("G83 X1. Z-5. R2. F100."), status(AlarmId::PeckWithoutQ));
  EXPECT_TRUE(m.motions().empty());
  EXPECT_EQ(Machine().block("G73 X1. Z-5. R2. Q0 F100."),
            status(AlarmId::PeckWithoutQ));
  EXPECT_EQ(Machine().block("G73 X1. Z-5. R2. Q1. F100."), 0);
}

// No time runs backwards: a negative dwell is PS0006, in G04 and in a cycle.
TEST(RuntimeCannedCycles, NegativeDwellAlarms) {
  EXPECT_EQ(Machine().block("G04 P-100"), status(AlarmId::IllegalMinusSign));
  EXPECT_EQ(Machine().block("G04 X-1."), status(AlarmId::IllegalMinusSign));
  EXPECT_EQ(Machine().block("G82 X1. Z-1. R1. P-500 F100."),
            status(AlarmId::IllegalMinusSign));
}

// With whole-unit literals (3401#0 = 1) G04 X2 is 2 s, as X2 is 2 mm.
TEST(RuntimeCannedCycles, DwellXFollowsDecimalPointInput) {
  Machine m(R"({"parameters": {"3401": 1}})");
  ASSERT_EQ(m.block("G04 X2"), 0);
  EXPECT_EQ(m.read(3001), 2000.0);
}

// G84.2 / G84.3, the Series 15 format of rigid tapping: G84 / G74 with
// M29 given, so Q pecks (high-speed, d = 0.1 mm); #4009 reads the code.
TEST(RuntimeCannedCycles, SeriesFifteenRigidTapping) {
  Machine m;
  ASSERT_EQ(m.block("G90 G00 X0 Y0 Z10."), 0);
  ASSERT_EQ(m.block("G99 G84.2 X10. Z-8. R2. Q5. F500."), 0);
  EXPECT_EQ(m.read(4009), 84.2);
  std::vector<double> depths;
  for (const mbrt_motion& motion : m.motions()) {
    depths.push_back(motion.end[2]);
  }
  EXPECT_EQ(depths, (std::vector<double>{10, 10, 2, -3, -2.9, -8, 2}));
  ASSERT_EQ(m.block("G80"), 0);
  EXPECT_EQ(m.read(4009), 80.0);
  ASSERT_EQ(m.block("G84.3 X20. Z-8. R2. F500."), 0);
  EXPECT_EQ(m.read(4009), 84.3);
}

} // namespace mbc::test
