// Chamfering and corner R at any angle (,C ,R) and ,A lines, on a mill
// and on a lathe. Every expected point is derived by hand in the comments.
#include <cmath>
#include <numbers>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr double kPrinted = 0.0005; // the derivations carry 4 decimals

// X40 ,C5 then Y30: the chamfer runs from 5 short of the corner (35, 0) to
// 5 past it (40, 5). With ,R5 the arc turns left (G03) about (35, 5).
TEST(RuntimeCornerBlends, RightAngleChamferAndCornerR) {
  Machine chamfer;
  expectPath(blocks(chamfer, {"G01 X40. ,C5. F300.", "Y30."}),
             {{35, 0}, {40, 5}, {40, 30}}, kPrinted);
  EXPECT_EQ(chamfer.motions()[1].line, 1); // the ,C block's
  EXPECT_EQ(chamfer.motions()[1].feed, 300.0);
  Machine round;
  expectPath(blocks(round, {"G01 X40. ,R5. F300.", "Y30."}),
             {{35, 0}, {40, 5}, {40, 30}}, kPrinted);
  EXPECT_EQ(round.motions()[1].kind, MBRT_MOTION_CCW);
  EXPECT_EQ(round.motions()[1].center[0], 35.0);
  EXPECT_EQ(round.motions()[1].center[1], 5.0);
}

// X40 ,R5 then a 45 degree line up to (80, 40): the centre lies 5 above
// the first line and 5 left of the second, at x = 45 - 5 sqrt 2; the arc
// leaves at (37.929, 0) and joins 5 tan 22.5 = 2.0711 along the second
// line, at (40 + 1.4645, 1.4645).
TEST(RuntimeCornerBlends, CornerRAtAnyAngle) {
  Machine m;
  expectPath(blocks(m, {"G01 X40. ,R5. F300.", "X80. Y40."}),
             {{45.0 - 5.0 * std::sqrt(2.0), 0},
              {40.0 + 2.0711 / std::sqrt(2.0), 2.0711 / std::sqrt(2.0)},
              {80, 40}},
             kPrinted);
  EXPECT_NEAR(m.motions()[1].center[0], 45.0 - 5.0 * std::sqrt(2.0), 0.0005);
  EXPECT_NEAR(m.motions()[1].center[1], 5.0, 0.0005);
}

// A line into a G02 arc from (40, 0) to (60, 20) about (60, 0), which
// leaves (40, 0) going up. ,C2 ends on the circle 2 from the corner:
// x = 40 + 2^2 / (2 * 20), y = sqrt(4 - 0.01). ,R5: the centre is 5 above
// the line and 25 from (60, 0), at (60 - sqrt 600, 5); the arc joins the
// circle at (60, 0) + 20 (-sqrt 600, 5) / 25.
TEST(RuntimeCornerBlends, LineIntoArc) {
  Machine chamfer;
  expectPath(blocks(chamfer, {"G01 X40. ,C2. F300.", "G02 X60. Y20. R20."}),
             {{38, 0}, {40.1, std::sqrt(3.99)}, {60, 20}}, kPrinted);
  EXPECT_EQ(chamfer.motions()[2].kind, MBRT_MOTION_CW);
  EXPECT_NEAR(chamfer.motions()[2].center[0], 60.0, 0.0005);
  EXPECT_NEAR(chamfer.motions()[2].center[1], 0.0, 0.0005);
  Machine round;
  const double x = 60.0 - std::sqrt(600.0);
  expectPath(blocks(round, {"G01 X40. ,R5. F300.", "G02 X60. Y20. R20."}),
             {{x, 0}, {60.0 - 20.0 * std::sqrt(600.0) / 25.0, 4}, {60, 20}},
             kPrinted);
  EXPECT_EQ(round.motions()[1].kind, MBRT_MOTION_CCW);
  EXPECT_NEAR(round.motions()[1].center[0], x, 0.0005);
  EXPECT_NEAR(round.motions()[1].center[1], 5.0, 0.0005);
}

// The mirror image of LineIntoArc about x = 40: the G02 arc from (20, 20)
// about (20, 0) ends at (40, 0) moving down, the line goes on along +X (a
// left turn). ,R5: the centre lies 5 above the line and 25 from (20, 0),
// at (20 + sqrt 600, 5); the arc leaves the circle at (20, 0) +
// 20 (sqrt 600, 5) / 25.
TEST(RuntimeCornerBlends, ArcIntoLine) {
  Machine m;
  const double x = 20.0 + std::sqrt(600.0);
  expectPath(
      blocks(m, {"G00 X20. Y20.", "G02 X40. Y0 R20. ,R5. F300.", "G01 X60."}),
      {{20, 20}, {20.0 + 20.0 * std::sqrt(600.0) / 25.0, 4}, {x, 0}, {60, 0}},
      kPrinted);
  EXPECT_EQ(m.motions()[2].kind, MBRT_MOTION_CCW);
  EXPECT_NEAR(m.motions()[2].center[0], x, 0.0005);
  EXPECT_NEAR(m.motions()[2].center[1], 5.0, 0.0005);
}

// Blocks may chain corners, and G91 words count from the virtual corner.
TEST(RuntimeCornerBlends, ChainsAndIncrementalWords) {
  Machine m;
  expectPath(blocks(m, {"G91 G01 X40. ,C5. F300.", "Y30. ,C5.", "X-40."}),
             {{35, 0}, {40, 5}, {40, 25}, {35, 30}, {0, 30}}, kPrinted);
}

// A lathe (diameters, G18: Z first, X second). X30 ,C1 from (X20 Z0):
// radius 15 - 1 = 14 (X28), then Z-1. Z-10 ,R2 into X40 ,A135: the ,A
// line from (Z-10, X30) rises 5 in radius over 5 in Z: it ends at Z-15.
// The arc turns right (G02) about (Z -10 + 2 tan 22.5, X 30 + 2 * 2):
// it leaves at Z-9.1716. ,A180 ,R1.5 then X56 Z-40 ,A90: the lines meet
// at (Z-40, X40); the arc leaves at Z-38.5 and joins at X43.
TEST(RuntimeCornerBlends, LatheDirectDrawing) {
  Machine m(R"({"series": "T"})");
  expectPath(
      blocks(m, {"G98 G00 X20. Z0", "G01 X30. ,C1. F100.", "Z-10. ,R2.",
                 "X40. ,A135.", ",A180. ,R1.5", "X56. Z-40. ,A90.", "X60."}),
      {{20, 0},
       {28, 0},
       {30, -1},
       {30, -10 + 2 * (std::sqrt(2.0) - 1)},
       {30 + 4 - 4 * std::sqrt(0.5),
        -10 - 2 * std::sqrt(0.5) + 2 * (std::sqrt(2.0) - 1)},
       {40, -15},
       {40, -38.5},
       {43, -40},
       {56, -40},
       {60, -40}},
      kPrinted);
  EXPECT_EQ(m.motions()[4].kind, MBRT_MOTION_CW);
  EXPECT_NEAR(m.motions()[4].center[1], 34.0, 0.0005); // X, a diameter
}

// ,A with one coordinate of the plane: the other one follows (G00 too).
TEST(RuntimeCornerBlends, AngleGivesTheOtherCoordinate) {
  Machine m;
  expectPath(
      blocks(m, {"G00 X10. ,A30.", "G01 Y20. ,A90. F100.", "Y10. ,A225."}),
      {{10, 10 * std::tan(std::numbers::pi / 6)}, {10, 20}, {0, 10}}, kPrinted);
  EXPECT_EQ(m.motions()[0].kind, MBRT_MOTION_RAPID);
}

// The run ends after a ,C block: its move goes as programmed.
TEST(RuntimeCornerBlends, HeldMoveRunsAtTheEnd) {
  Machine m;
  blocks(m, {"G01 X40. ,C5. F300."});
  EXPECT_TRUE(m.motions().empty());
  mbrt_finish(m.ctx(), MBRT_END_M02_M30);
  expectPath(ends(m), {{40, 0}}, kPrinted);
}

TEST(RuntimeCornerBlends, Alarms) {
  const struct {
    const char* held;
    const char* next;
    AlarmId alarm;
  } cases[] = {
      {"X40. ,C2. ,R2.", "", AlarmId::TooManyAddressCommands},
      {"G00 X40. ,C2.", "", AlarmId::TooManyAddressCommands},
      {"G04 X1. ,C2.", "", AlarmId::TooManyAddressCommands},
      {"G02 X40. R20. ,A30.", "", AlarmId::TooManyAddressCommands},
      {"X40. Y10. ,A30.", "", AlarmId::TooManyAddressCommands},
      {"Y10. ,A0.", "", AlarmId::NoSolutionOfBlockEnd},
      {"X40. ,C2.", "M08", AlarmId::MissingMoveAfterCorner},
      {"X40. ,C2.", "G00 Y30.", AlarmId::NotG01AfterCorner},
      {"X40. ,C2.", "G04 X1.", AlarmId::NotG01AfterCorner},
      {"X40. ,C50.", "Y30.", AlarmId::MissingCornerMove},
      {"X40. ,C2.", "Y1.", AlarmId::MissingCornerMove},
      {"X40. ,R5.", "X80.", AlarmId::MissingCornerMove},
      {"X40. ,R31.", "Y30.", AlarmId::MissingCornerMove},
      {"X40. ,R5.", "G03 X40. Y8. R4.", AlarmId::MissingCornerMove},
      {"X40. ,C2.", "Y30. Z-5.", AlarmId::Unsupported},
      {",A30.", "X50.", AlarmId::NoEndPointAndAngle},
      {",A30.", "M08", AlarmId::NoEndPointAndAngle},
      {",A0.", "X50. Y0 ,A180.", AlarmId::NoSolutionOfBlockEnd},
      {"X40. ,R5.", "G19 Y30.", AlarmId::MissingMoveAfterCorner},
      {",A30.", "G18 X50. Z10. ,A90.", AlarmId::MissingMoveAfterCorner},
  };

  for (const auto& c : cases) {
    Machine m;
    ASSERT_EQ(m.block("G01 F100."), 0);
    const mbrt_status held = m.block(c.held);
    const mbrt_status next =
        held == 0 && *c.next != '\0' ? m.block(c.next) : held;
    EXPECT_EQ(next, status(c.alarm)) << c.held << " / " << c.next;
    EXPECT_TRUE(m.motions().empty()) << c.held << " / " << c.next;
  }
}

} // namespace
} // namespace mbc::test
