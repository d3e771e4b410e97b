// The stored stroke check 1 (stroke_check.h): parameters 1320/1321 bound
// each axis in machine coordinates; a move past an end alarms at its block
// before it moves. Expectations are derived by hand from the limits and
// the geometry of each move.
#include <gtest/gtest.h>

#include <vector>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kMill = R"({"parameters": {
    "1320": [100, 50, 10], "1321": [-100, -50, -200]}})";

/// Runs `texts` at lines 1, 2, ...; the status of the first that fails (0
/// when none does) and its line.
std::pair<mbrt_status, int>
runUntilAlarm(Machine& m, std::initializer_list<const char*> texts) {
  int line = 1;
  for (const char* text : texts) {
    if (const mbrt_status status = m.block(text, line)) {
      return {status, line};
    }
    ++line;
  }
  return {0, 0};
}

/// Runs `text`, which must raise `alarm` with `reach` in its report.
void expectOvertravel(Machine& m, const std::string& text, AlarmId alarm,
                      const char* reach) {
  EXPECT_EQ(m.block(text), status(alarm)) << text;
  EXPECT_NE(m.report().find(reach), std::string::npos) << m.report();
}

TEST(RuntimeStrokeCheck, EndsAreInsideAndPastThemNothingMoves) {
  Machine m(kMill);
  // Both ends reached exactly: allowed.
  const auto [ok, okLine] =
      runUntilAlarm(m, {"G90 G00 X100. Y-50.", "Z10.", "X-100. Y50. Z-200."});
  ASSERT_EQ(ok, 0) << m.report();
  const std::size_t moves = m.motions().size();
  EXPECT_EQ(m.block("G01 X100.001 F100.", 7), status(AlarmId::OvertravelPlus));
  EXPECT_EQ(m.motions().size(), moves); // the tool stays where it stood
  EXPECT_NE(m.report().find("test.nc:7"), std::string::npos) << m.report();
  EXPECT_NE(m.report().find("X would reach 100.001 mm"), std::string::npos)
      << m.report();
  EXPECT_EQ(m.read(5021), -100.0);
}

TEST(RuntimeStrokeCheck, TheAxisThatCrossesFirstIsNamed) {
  // From (0, 0) to (200, 60): X passes 100 at 1/2, Y passes 50 at 5/6.
  Machine m(kMill);
  expectOvertravel(m, "G90 G01 X200. Y60. F500.", AlarmId::OvertravelPlus,
                   "X would reach 200.000");
  // To (110, -100): Y passes -50 at 1/2, X passes 100 at 10/11.
  Machine n(kMill);
  expectOvertravel(n, "G90 G01 X110. Y-100. F500.", AlarmId::OvertravelMinus,
                   "Y would reach -100.000");
}

TEST(RuntimeStrokeCheck, AnArcIsCheckedOverItsExtentInEveryPlane) {
  struct Case {
    std::vector<const char*> within; // from X0 Y0 Z0, each within
    const char* past;
    AlarmId alarm;
    const char* reach;
  };

  const Case cases[] = {
      // G17: from (60, 0) about (0, 0) counterclockwise to (0, 60): both
      // ends within X <= 100 and Y <= 50, the arc through Y 60 at 90 deg.
      {{"G90 G00 X60. Y0"},
       "G03 X0 Y60. I-60. J0 F300.",
       AlarmId::OvertravelPlus,
       "Y would reach 60.000"},
      // Clockwise the long way through X -40 and Y -40 (and -45), within;
      // then about (0, -20) with radius 40 down to Y -60, past -50.
      {{"G90 G00 X40. Y0", "G02 X0 Y40. I-40. J0 F300.", "G00 X45. Y0",
        "G02 X0 Y45. R-45.", "G00 X40. Y-20."},
       "G02 X-40. Y-20. R40.",
       AlarmId::OvertravelMinus,
       "Y would reach -60.000"},
      // G18 (Z X, counterclockwise from Z towards X): about Z -20, X 0
      // between X -40 and X 40, G02 and G03 back pass Z -60 (within -200),
      // G03 from X -40 passes Z 20 (past 10).
      {{"G90 G18 G00 X-40. Z-20.", "G02 X40. Z-20. R40. F300.",
        "G03 X-40. Z-20. R40."},
       "G03 X40. Z-20. R40.",
       AlarmId::OvertravelPlus,
       "Z would reach 20.000"},
      // G19 (Y Z): about Y 0, Z -100 with radius 55 from Z -155 to Z -45,
      // G03 passes Y 55 and G02 Y -55, both past the ends at +-50.
      {{"G90 G19 G00 Y0 Z-155."},
       "G03 Y0 Z-45. J0 K55. F300.",
       AlarmId::OvertravelPlus,
       "Y would reach 55.000"},
      {{"G90 G19 G00 Y0 Z-155."},
       "G02 Y0 Z-45. J0 K55. F300.",
       AlarmId::OvertravelMinus,
       "Y would reach -55.000"},
      // A helix: the plane's axes within, the third axis past its end.
      {{"G90 G17 G00 X20. Y0 Z0"},
       "G03 X20. Y0 I-20. J0 Z15. F300.",
       AlarmId::OvertravelPlus,
       "Z would reach 15.000"},
  };
  for (const Case& c : cases) {
    Machine m(kMill);
    for (const char* text : c.within) {
      ASSERT_EQ(m.block(text), 0) << text << m.report();
    }
    expectOvertravel(m, c.past, c.alarm, c.reach);
  }
}

TEST(RuntimeStrokeCheck, FramesMoveTheProgramNotTheStroke) {
  // G68 R90 about X10 Y0: program X40 Y0 is machine X 10, Y 30 (within);
  // X70 is machine Y 60, past 50 on Y, though X70 is within X's 100.
  // (Y is given: set with the tool at machine zero, the frame makes the
  // program position X10 Y10 there.)
  Machine m(kMill);
  ASSERT_EQ(m.block("G90 G17 G68 X10. Y0 R90."), 0) << m.report();
  ASSERT_EQ(m.block("G01 X40. Y0 F500."), 0) << m.report();
  EXPECT_EQ(m.read(5021), 10.0);
  EXPECT_EQ(m.read(5022), 30.0);
  expectOvertravel(m, "X70.", AlarmId::OvertravelPlus, "Y would reach 60.000");
}

TEST(RuntimeStrokeCheck, StrokesAreInMillimetresAndDegreesWhateverG20) {
  Machine m(R"({"axes": ["X", "Y", "Z", "A"], "parameters": {
      "1320": [100, 50, 10, 90], "1321": [-100, -50, -200, 0]}})");
  ASSERT_EQ(m.block("G20 G90 G00 X3.9 A90."), 0) << m.report(); // 99.06 mm
  expectOvertravel(m, "X3.95", AlarmId::OvertravelPlus,
                   "X would reach 100.330 mm");
  Machine a(R"({"axes": ["X", "Y", "Z", "A"], "parameters": {
      "1320": [100, 50, 10, 90], "1321": [-100, -50, -200, 0]}})");
  expectOvertravel(a, "G90 G00 A90.001", AlarmId::OvertravelPlus,
                   "A would reach 90.001 deg");
}

TEST(RuntimeStrokeCheck, AxesWithoutAStroke) {
  // Z's 1320 below its 1321: FANUC's infinite stroke. A rolls over
  // (1008#0): its position is always within one turn.
  Machine m(R"({"axes": ["X", "Y", "Z", "A"], "parameters": {
      "1008": [0, 0, 0, 1],
      "1320": [100, 50, -1, 90], "1321": [-100, -50, 1, 0]}})");
  EXPECT_EQ(m.block("G90 G00 Z-5000. A720."), 0) << m.report();
  EXPECT_EQ(m.block("G91 A-1000."), 0) << m.report();
  // The C API says which axes the run checks, and their ends.
  double low = 0.0;
  double high = 0.0;
  ASSERT_EQ(mbrt_get_stroke(m.ctx(), 0, &low, &high), 1);
  EXPECT_EQ(low, -100.0);
  EXPECT_EQ(high, 100.0);
  EXPECT_EQ(mbrt_get_stroke(m.ctx(), 2, &low, &high), 0); // infinite
  EXPECT_EQ(mbrt_get_stroke(m.ctx(), 3, &low, &high), 0); // rolls over
  EXPECT_EQ(mbrt_get_stroke(m.ctx(), 4, &low, &high), 0); // no such axis
  // Axes the arrays leave out have no stroke either.
  Machine short_(R"({"parameters": {"1320": [100], "1321": [-100]}})");
  EXPECT_EQ(short_.block("G90 G00 Y-900. Z900."), 0) << short_.report();
  EXPECT_EQ(short_.block("X-100.5"), status(AlarmId::OvertravelMinus));
  // Unset, PRM reads the infinite stroke.
  Machine none;
  double v = 0.0;
  ASSERT_EQ(
      mbrt_read_parameter(none.ctx(), MBRT_PARAMETER_AXIS, 1320, 0, 1, &v), 0);
  EXPECT_EQ(v, -999999.0);
}

TEST(RuntimeStrokeCheck, ProgramSetStrokesHoldUntilReset) {
  Machine m;
  ASSERT_EQ(m.block("G90 G00 X150."), 0);
  // The stroke set with the tool beyond its end: the tool may come back,
  // not go farther.
  for (const char* text :
       {"G10 L52", "N1320 P1 R100.", "N1321 P1 R-100.", "G11"}) {
    ASSERT_EQ(m.block(text), 0) << text << m.report();
  }
  EXPECT_EQ(m.block("G01 X120. F500."), 0) << m.report();
  EXPECT_EQ(m.block("X130."), status(AlarmId::OvertravelPlus));
  mbrt_reset(m.ctx());
  mbrt_start(m.ctx(), "O1000");
  EXPECT_EQ(m.block("G90 G00 X500."), 0) << m.report();
}

TEST(RuntimeStrokeCheck, AStrokeNeedsBothEnds) {
  EXPECT_NE(profileError(R"({"parameters": {"1320": [1, 2, 3]}})")
                .find("\"parameters.1320\" needs 1321 too"),
            std::string::npos);
  EXPECT_NE(profileError(R"({"parameters": {"1321": [1, 2, 3]}})")
                .find("\"parameters.1321\" needs 1320 too"),
            std::string::npos);
}

} // namespace
} // namespace mbc::test
