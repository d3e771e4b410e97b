// Circular motion through the C ABI: centres from I J K and from R, both
// directions, the three planes, helices, full circles, the radius tolerance
// and the simulated time of arcs.
#include <cmath>
#include <numbers>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RuntimeArc, QuarterCircleFromIJ) {
  Machine m;
  ASSERT_EQ(m.block("G00 X10. Y0", 1), 0);
  ASSERT_EQ(m.block("G03 X0 Y10. I-10. F100", 2), 0);
  ASSERT_EQ(m.json().size(), 2u);
  EXPECT_EQ(
      m.json()[1],
      "{\"motion\":\"ccw\",\"x\":0,\"y\":10,\"z\":0,\"mx\":0,\"my\":10,\"mz\":"
      "0,\"f\":100,\"cx\":0,\"cy\":0,\"line\":2,\"prog\":\"O1000\"}\n");
  const mbrt_motion& arc = m.motions()[1];
  EXPECT_EQ(arc.plane, 17);
  EXPECT_EQ(arc.center_axes[0], 'X');
  EXPECT_EQ(arc.center_axes[1], 'Y');
  // 60 ms of rapid, then a quarter of 2 pi 10 mm at 100 mm/min.
  EXPECT_EQ(m.read(3001), std::floor(60.0 + 5.0 * kPi / 100.0 * 60000.0));
}

TEST(RuntimeArc, ClockwiseFromIJ) {
  Machine m;
  ASSERT_EQ(m.block("G00 X0 Y10."), 0);
  ASSERT_EQ(m.block("G02 X10. Y0 I0 J-10. F100"), 0);
  const mbrt_motion& arc = m.motions()[1];
  EXPECT_EQ(arc.kind, MBRT_MOTION_CW);
  EXPECT_EQ(arc.center[0], 0.0);
  EXPECT_EQ(arc.center[1], 0.0);
  EXPECT_EQ(arc.end[0], 10.0);
  EXPECT_EQ(arc.end[1], 0.0);
}

TEST(RuntimeArc, CentreIsAbsoluteInTheWorkpieceSystem) {
  Machine m(R"({"work_offsets": {"G55": [100, 50, 0]}})");
  ASSERT_EQ(m.block("G55 G00 X12. Y3."), 0);
  ASSERT_EQ(m.block("G91 G02 X-6. Y-2. I-2. J-4. F50"), 0);
  const mbrt_motion& arc = m.motions()[1];
  EXPECT_EQ(arc.center[0], 10.0);
  EXPECT_EQ(arc.center[1], -1.0);
  EXPECT_EQ(arc.end[0], 6.0);
  EXPECT_EQ(arc.end[1], 1.0);
  EXPECT_EQ(m.read(5021), 106.0);
}

struct RadiusCase {
  const char* block;
  int kind;
  double cx;
  double cy;
  double sweep; // radians
};

TEST(RuntimeArc, CentreFromRadius) {
  // From (0,0) to (10,10) with |R| = 10: the centre is (10,0) or (0,10).
  const RadiusCase cases[] = {
      {"G02 X10. Y10. R10. F100", MBRT_MOTION_CW, 10, 0, kPi / 2},
      {"G02 X10. Y10. R-10. F100", MBRT_MOTION_CW, 0, 10, 3 * kPi / 2},
      {"G03 X10. Y10. R10. F100", MBRT_MOTION_CCW, 0, 10, kPi / 2},
      {"G03 X10. Y10. R-10. F100", MBRT_MOTION_CCW, 10, 0, 3 * kPi / 2},
  };
  for (const RadiusCase& c : cases) {
    Machine m;
    ASSERT_EQ(m.block(c.block), 0) << c.block;
    ASSERT_EQ(m.motions().size(), 1u);
    const mbrt_motion& arc = m.motions()[0];
    EXPECT_EQ(arc.kind, c.kind) << c.block;
    EXPECT_NEAR(arc.center[0], c.cx, 1e-9) << c.block;
    EXPECT_NEAR(arc.center[1], c.cy, 1e-9) << c.block;
    EXPECT_EQ(arc.end[0], 10.0);
    EXPECT_EQ(arc.end[1], 10.0);
    EXPECT_NEAR(m.read(3001), 10.0 * c.sweep / 100.0 * 60000.0, 1.0) << c.block;
  }
}

// An R that cannot reach the end point is PS0020 (no arc of that radius
// goes there); short of half the chord by the radius tolerance (3410,
// 0.02 mm) at most, it is stretched to the semicircle.
TEST(RuntimeArc, RadiusShortOfHalfTheChord) {
  Machine m;
  EXPECT_EQ(m.block("G02 X10. Y0 R1. F100", 2),
            status(AlarmId::ArcRadiusTolerance));
  EXPECT_EQ(m.report(), "test.nc:2: alarm PS0020: OVER TOLERANCE OF RADIUS: "
                        "R1 cannot reach the end point: half the distance to "
                        "it is 5.0000\n");
  EXPECT_TRUE(m.motions().empty());
  Machine near;
  ASSERT_EQ(near.block("G02 X10.03 Y0 R5. F100"), 0);
  EXPECT_NEAR(near.motions()[0].center[0], 5.015, 1e-12);
  EXPECT_NEAR(near.motions()[0].center[1], 0.0, 1e-12);
  Machine unchecked(R"({"parameters": {"3410": 0}})");
  ASSERT_EQ(unchecked.block("G02 X10. Y0 R1. F100"), 0);
  EXPECT_NEAR(unchecked.motions()[0].center[0], 5.0, 1e-12);
}

TEST(RuntimeArc, RadiusWithStartAtTheEndMakesNoMotion) {
  Machine m;
  ASSERT_EQ(m.block("G00 X10."), 0);
  ASSERT_EQ(m.block("G02 X10. Y0 R5. F100"), 0);
  ASSERT_EQ(m.block("G02 R5."), 0);
  EXPECT_EQ(m.motions().size(), 1u);
}

TEST(RuntimeArc, FullCircle) {
  Machine m;
  ASSERT_EQ(m.block("G00 X10."), 0);
  ASSERT_EQ(m.block("G02 I-10. F100", 2), 0);
  ASSERT_EQ(m.block("G03 X10. Y0 I-10.", 3), 0);
  ASSERT_EQ(m.motions().size(), 3u);
  EXPECT_EQ(
      m.json()[1],
      "{\"motion\":\"cw\",\"x\":10,\"y\":0,\"z\":0,\"mx\":10,\"my\":0,\"mz\":0,"
      "\"f\":100,\"cx\":0,\"cy\":0,\"line\":2,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(m.motions()[2].kind, MBRT_MOTION_CCW);
  // Two full circles of 2 pi 10 mm at F100 after 60 ms of rapid.
  EXPECT_EQ(m.read(3001), std::floor(60.0 + 2 * 20 * kPi / 100 * 60000));
}

TEST(RuntimeArc, Helix) {
  Machine m;
  ASSERT_EQ(m.block("G00 X10."), 0);
  ASSERT_EQ(m.block("G03 X0 Y10. Z-5. I-10. F100"), 0);
  const mbrt_motion& arc = m.motions()[1];
  EXPECT_EQ(arc.end[2], -5.0);
  EXPECT_EQ(arc.center[0], 0.0);
  // F is along the arc in the plane: Z only follows.
  EXPECT_EQ(m.read(3001), std::floor(60.0 + 5.0 * kPi / 100.0 * 60000.0));
}

TEST(RuntimeArc, ZXPlane) {
  Machine m;
  ASSERT_EQ(m.block("G00 X10. Z0"), 0);
  ASSERT_EQ(m.block("G18 G02 X0 Z10. I-10. K0 F100", 2), 0);
  EXPECT_EQ(
      m.json()[1],
      "{\"motion\":\"cw\",\"x\":0,\"y\":0,\"z\":10,\"mx\":0,\"my\":0,\"mz\":10,"
      "\"f\":100,\"cz\":0,\"cx\":0,\"line\":2,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(m.read(4002), 18.0);
}

TEST(RuntimeArc, YZPlane) {
  Machine m;
  ASSERT_EQ(m.block("G00 Y10. Z5."), 0);
  ASSERT_EQ(m.block("G19 G03 Y0 Z15. J-10. F100", 2), 0);
  EXPECT_EQ(
      m.json()[1],
      "{\"motion\":\"ccw\",\"x\":0,\"y\":0,\"z\":15,\"mx\":0,\"my\":0,\"mz\":"
      "15,\"f\":100,\"cy\":0,\"cz\":5,\"line\":2,\"prog\":\"O1000\"}\n");
}

TEST(RuntimeArc, RadiusTolerance) {
  Machine m;
  ASSERT_EQ(m.block("G00 X10."), 0);
  ASSERT_EQ(m.block("G03 X0 Y10.01 I-10. F100"), 0); // within 0.02
  Machine n;
  ASSERT_EQ(n.block("G00 X10."), 0);
  EXPECT_EQ(n.block("G03 X0 Y10.5 I-10. F100", 2),
            status(AlarmId::ArcRadiusTolerance));
  EXPECT_EQ(n.report(), "test.nc:2: alarm PS0020: OVER TOLERANCE OF RADIUS: "
                        "radius 10.0000 at the start, 10.5000 at the end\n");
  Machine unchecked(R"({"parameters": {"3410": 0}})");
  ASSERT_EQ(unchecked.block("G00 X10."), 0);
  EXPECT_EQ(unchecked.block("G03 X0 Y10.5 I-10. F100"), 0);
}

// Parameter 3403#5 CIR: 0 (FANUC's default) feeds straight to the end
// point, 1 raises PS0022.
TEST(RuntimeArc, ArcWithoutCentre) {
  Machine m;
  ASSERT_EQ(m.block("G02 X10. Y10. F100"), 0);
  ASSERT_EQ(m.motions().size(), 1u);
  EXPECT_EQ(m.motions()[0].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.read(5001), 10.0);
  EXPECT_EQ(m.read(4001), 2.0);
  Machine cir(R"({"parameters": {"3403": 32}})");
  EXPECT_EQ(cir.block("G02 X10. Y10. F100"), status(AlarmId::ArcNoRadius));
  EXPECT_EQ(cir.report(), "test.nc:1: alarm PS0022: R OR I,J,K COMMAND NOT "
                          "FOUND: arc without R or I, J, K\n");
}

TEST(RuntimeArc, PlaneAxesMustExist) {
  Machine m(R"({"axes": ["X", "Y"]})");
  EXPECT_EQ(m.block("G18 G02 X1. I1. F100"),
            status(AlarmId::IllegalPlaneSelect));
  EXPECT_NE(m.report().find("G18 arcs need axes Z and X"), std::string::npos);
}

TEST(RuntimeArc, InchArc) {
  Machine m(R"({"units": "inch"})");
  ASSERT_EQ(m.block("G00 X1."), 0);
  ASSERT_EQ(m.block("G03 X0 Y1. I-1. F10.5", 2), 0);
  EXPECT_EQ(
      m.json()[1],
      "{\"motion\":\"ccw\",\"x\":0,\"y\":1,\"z\":0,\"mx\":0,\"my\":1,\"mz\":0,"
      "\"f\":10.5,\"cx\":0,\"cy\":0,\"line\":2,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(m.motions()[1].decimals, 4);
}

} // namespace

// F is the feed along the arc in its plane; the helix's linear axis only
// follows (FANUC helical interpolation): a full circle of radius 5 at F100
// takes 10 pi / 100 minutes whatever Z travels.
TEST(RuntimeArc, HelixTakesTheArcTimeAtF) {
  Machine m;
  ASSERT_EQ(m.block("G17 G90 G01 X5. Y0 F100."), 0);
  const double before = m.read(3001);
  ASSERT_EQ(m.block("G02 X5. Y0 Z-10. I-5."), 0);
  EXPECT_NEAR(m.read(3001) - before, 10.0 * kPi / 100.0 * 60000.0, 1.0);
}

} // namespace mbc::test
