// G10 L52 ... G11, programmable parameter input (parameter_input.h): each
// block between sets one parameter, checked as the profile's are; what a
// program sets lasts until mbrt_reset.
#include <gtest/gtest.h>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

TEST(RuntimeParameterInput, BlocksBetweenG10L52AndG11SetParameters) {
  Machine m;
  ASSERT_EQ(m.block("G10 L52"), 0);
  ASSERT_EQ(m.block("N5114 R0.5"), 0);      // a real: the G73 retract
  ASSERT_EQ(m.block("N3403 Q5 R1"), 0);     // one bit: CIR
  ASSERT_EQ(m.block("N1241 P2 R-120."), 0); // per axis: Y's 2nd reference
  ASSERT_EQ(m.block("G11"), 0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 5114), 0.5);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 3403), 32.0);
  // After G11 the blocks are blocks again: X moves.
  ASSERT_EQ(m.block("G90 G00 X10."), 0);
  ASSERT_EQ(m.motions().size(), 1U);
  // G30 P2 goes to the 2nd reference position the program set.
  ASSERT_EQ(m.block("G91 G30 P2 Y0"), 0);
  EXPECT_EQ(m.read(5022), -120.0);
  // A bit set with Q keeps the others; R alone sets the whole byte.
  ASSERT_EQ(m.block("G10 L52"), 0);
  ASSERT_EQ(m.block("N5400 R128"), 0);
  ASSERT_EQ(m.block("N5400 Q0 R1"), 0);
  ASSERT_EQ(m.block("G11"), 0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 5400), 129.0);
}

TEST(RuntimeParameterInput, WhatMbcCannotFollowStops) {
  struct Case {
    const char* block;
    AlarmId alarm;
    const char* text;
  };

  const Case cases[] = {
      {"N1322 P1 R500.", AlarmId::Unsupported,
       "parameter 1322 is not one mbc models"},
      {"N1006 P1 R1", AlarmId::Unsupported, "says what the machine is"},
      {"N3410 R-1.", AlarmId::IllegalExpressionFormat,
       "must be a number from 0"},
      {"N6004 Q9 R1", AlarmId::IllegalExpressionFormat, "Q is the bit"},
      {"N6004 Q0 R1", AlarmId::Unsupported, "holds for a whole run"},
      {"N3401 R64", AlarmId::Unsupported, "the G code system"},
      {"N1241 R5.", AlarmId::IllegalExpressionFormat, "needs P"},
      {"N5114", AlarmId::IllegalExpressionFormat, "R the value"},
      {"N6050 R81", AlarmId::Unsupported, "G code mbc executes"},
      {"G01 X10.", AlarmId::IllegalExpressionFormat, "until G11"},
  };
  for (const Case& c : cases) {
    Machine m;
    ASSERT_EQ(m.block("G10 L52"), 0);
    EXPECT_EQ(m.block(c.block), status(c.alarm)) << c.block;
    EXPECT_NE(m.report().find(c.text), std::string::npos) << m.report();
  }
}

TEST(RuntimeParameterInput, ResetBringsTheProfilesParametersBack) {
  Machine m(R"({"parameters": {"5114": 0.2}})");
  ASSERT_EQ(m.block("G10 L52"), 0);
  ASSERT_EQ(m.block("N5114 R0.7"), 0);
  ASSERT_EQ(m.block("N3401 Q0 R1"), 0); // DPI: X10 is 10 mm
  ASSERT_EQ(m.block("G11"), 0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 5114), 0.7);
  mbrt_reset(m.ctx());
  EXPECT_EQ(mbrt_parameter(m.ctx(), 5114), 0.2);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 3401), 0.0);
  mbrt_start(m.ctx(), "O1000");
  ASSERT_EQ(m.block("G90 G00 X10"), 0); // 0.010 mm again
  EXPECT_EQ(m.read(5001), 0.01);
}

// PRM (mbrt_read_parameter): the values a profile may set, with their
// defaults; what a machine cannot tell is an alarm, never a guess.
TEST(RuntimeParameterRead, ValuesBitsAxesAndAlarms) {
  Machine m(R"({"axes": ["X", "Y", "Z", "C"], "parameters": {"5400": 129,
      "1241": [10, 20, 30, 40]}})");
  double v = -1.0;
  ASSERT_EQ(mbrt_read_parameter(m.ctx(), 0, 3410, 0, 0, &v), 0);
  EXPECT_EQ(v, 0.02); // the default
  ASSERT_EQ(mbrt_read_parameter(m.ctx(), MBRT_PARAMETER_BIT, 5400, 7, 0, &v),
            0);
  EXPECT_EQ(v, 1.0);
  ASSERT_EQ(mbrt_read_parameter(m.ctx(), MBRT_PARAMETER_BIT, 5400, 6, 0, &v),
            0);
  EXPECT_EQ(v, 0.0);
  ASSERT_EQ(mbrt_read_parameter(m.ctx(), MBRT_PARAMETER_AXIS, 1241, 0, 3, &v),
            0);
  EXPECT_EQ(v, 30.0);
  // 1006 as the profile derived it: C is rotary (#0 ROT).
  ASSERT_EQ(mbrt_read_parameter(m.ctx(),
                                MBRT_PARAMETER_BIT | MBRT_PARAMETER_AXIS, 1006,
                                0, 4, &v),
            0);
  EXPECT_EQ(v, 1.0);

  struct Case {
    int form;
    double n, bit, axis;
    AlarmId alarm;
  };

  const Case cases[] = {
      {0, 1322, 0, 0, AlarmId::Unsupported},        // not modelled
      {0, 1241, 0, 0, AlarmId::ArgumentOutOfRange}, // needs an axis
      {MBRT_PARAMETER_AXIS, 3410, 0, 1, AlarmId::ArgumentOutOfRange},
      {MBRT_PARAMETER_AXIS, 1241, 0, 5, AlarmId::ArgumentOutOfRange},
      {MBRT_PARAMETER_BIT, 3410, 0, 0, AlarmId::ArgumentOutOfRange},
      {MBRT_PARAMETER_BIT, 5400, 8, 0, AlarmId::ArgumentOutOfRange},
  };
  for (const Case& c : cases) {
    Machine fresh;
    EXPECT_EQ(mbrt_read_parameter(fresh.ctx(), c.form, c.n, c.bit, c.axis, &v),
              status(c.alarm))
        << c.n;
  }
}

} // namespace
} // namespace mbc::test
