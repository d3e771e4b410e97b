// Polar coordinates (runtime/src/machine/polar.cpp). Every expected point is
// worked out by hand from the FANUC rules: radius on the plane's first
// axis, angle in degrees on the second, counter-clockwise from the first
// axis; the pole at the program zero (the G52 origin) unless a G91 radius
// measures from the current position; a word left out keeps the current
// radius or angle; a G91 angle adds to the current angle.
#include "runtime_test_support.h"

namespace mbc::test {

TEST(RuntimePolar, AbsoluteRadiusAndAngleAboutTheProgramZero) {
  Machine m;
  ASSERT_EQ(m.block("G17 G90 G16"), 0);
  EXPECT_EQ(m.read(4017), 16.0);
  ASSERT_EQ(m.block("G01 X100. Y30. F100."), 0);
  EXPECT_EQ(m.read(5001), 86.603); // 100 cos 30
  EXPECT_EQ(m.read(5002), 50.0);   // 100 sin 30
  ASSERT_EQ(m.block("Y150."), 0);  // radius left out: still 100
  EXPECT_EQ(m.read(5001), -86.603);
  EXPECT_EQ(m.read(5002), 50.0);
  ASSERT_EQ(m.block("X50."), 0); // angle left out: still 150 degrees
  EXPECT_EQ(m.read(5001), -43.301);
  EXPECT_EQ(m.read(5002), 25.0);
  ASSERT_EQ(m.block("G15"), 0);
  EXPECT_EQ(m.read(4017), 15.0);
  ASSERT_EQ(m.block("X10. Y20."), 0); // Cartesian again
  EXPECT_EQ(m.read(5001), 10.0);
  EXPECT_EQ(m.read(5002), 20.0);
}

TEST(RuntimePolar, IncrementalAngleKeepsThePoleAtZero) {
  Machine m;
  ASSERT_EQ(m.block("G90 G16 G00 X100. Y30."), 0);
  ASSERT_EQ(m.block("G91 Y120."), 0); // 30 + 120 = 150 degrees, radius 100
  EXPECT_EQ(m.read(5001), -86.603);
  EXPECT_EQ(m.read(5002), 50.0);
  ASSERT_EQ(m.block("Y120."), 0); // 270 degrees
  EXPECT_EQ(m.read(5001), 0.0);
  EXPECT_EQ(m.read(5002), -100.0);
}

TEST(RuntimePolar, IncrementalRadiusMeasuresFromTheCurrentPosition) {
  Machine m;
  ASSERT_EQ(m.block("G90 G00 X10. Y0"), 0);
  ASSERT_EQ(m.block("G16 G91 X5. Y90."), 0);
  // The pole is (10, 0); the angle is the current 0 degrees + 90.
  EXPECT_EQ(m.read(5001), 10.0);
  EXPECT_EQ(m.read(5002), 5.0);
}

TEST(RuntimePolar, TheLocalOriginIsThePole) {
  Machine m;
  ASSERT_EQ(m.block("G90 G52 X100. Y50."), 0);
  ASSERT_EQ(m.block("G16 G00 X20. Y90."), 0);
  EXPECT_EQ(m.read(5001), 0.0); // local coordinates: 20 up from the origin
  EXPECT_EQ(m.read(5002), 20.0);
  EXPECT_EQ(m.motions().back().end[0], 100.0); // work coordinates
  EXPECT_EQ(m.motions().back().end[1], 70.0);
}

TEST(RuntimePolar, OtherPlanesAndAxesOutsideThePlane) {
  Machine m;
  // G18: Z is the radius, X the angle from +Z towards +X.
  ASSERT_EQ(m.block("G18 G90 G16 G00 Z10. X90. Y7."), 0);
  EXPECT_EQ(m.read(5001), 10.0);
  EXPECT_EQ(m.read(5002), 7.0); // Y is no plane word: as written
  EXPECT_EQ(m.read(5003), 0.0);
}

TEST(RuntimePolar, G28WithPlaneWordsIsNotModelled) {
  Machine m;
  ASSERT_EQ(m.block("G16"), 0);
  EXPECT_EQ(m.block("G91 G28 Z0"), 0);
  EXPECT_EQ(m.block("G28 X0 Y0"), status(AlarmId::Unsupported));
}

} // namespace mbc::test
