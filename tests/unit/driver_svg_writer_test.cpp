// --svg (driver/svg_writer.cpp): path data for lines and arcs, the box
// that holds every arc, and the scale.
#include "driver/svg_writer.h"

#include <gtest/gtest.h>

#include <string>

namespace mbc::driver {
namespace {

mbrt_motion move(int kind, double x0, double y0, double x1, double y1) {
  mbrt_motion m{};
  m.kind = kind;
  m.axis_count = 3;
  m.axis_names = "XYZ";
  m.start[0] = x0;
  m.start[1] = y0;
  m.end[0] = x1;
  m.end[1] = y1;
  m.programmed[0] = x1;
  m.programmed[1] = y1;
  m.plane = 17;
  m.center_axes[0] = 'X';
  m.center_axes[1] = 'Y';
  m.decimals = 3;
  return m;
}

std::string drawing(std::initializer_list<mbrt_motion> moves) {
  SvgWriter svg;
  for (const mbrt_motion& m : moves) {
    svg.add(m);
  }
  return svg.document();
}

TEST(SvgWriter, RapidsDashedFeedsSolidOnePathEach) {
  const std::string svg = drawing({move(MBRT_MOTION_RAPID, 0, 0, 10, 0),
                                   move(MBRT_MOTION_LINEAR, 10, 0, 10, 5),
                                   move(MBRT_MOTION_LINEAR, 10, 5, 0, 5),
                                   move(MBRT_MOTION_RAPID, 0, 5, 0, 0)});
  EXPECT_NE(svg.find("class=\"rapid\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("d=\"M0 0L10 0M0 -5L0 0\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("d=\"M10 0L10 -5L0 -5\""), std::string::npos) << svg;
}

TEST(SvgWriter, ArcsAreArcsAndTheBoxHoldsThem) {
  mbrt_motion half = move(MBRT_MOTION_CCW, 10, 0, -10, 0); // over the top
  mbrt_motion full = move(MBRT_MOTION_CW, -10, 0, -10, 0);
  full.center[0] = -20;
  const std::string svg = drawing({half, full});
  // Counter-clockwise is sweep flag 0 with y pointing down.
  EXPECT_NE(svg.find("A10 10 0 0 0 -10 0"), std::string::npos) << svg;
  // A full circle: two halves, clockwise (flag 1).
  EXPECT_NE(svg.find("A10 10 0 0 1 -30 0A10 10 0 0 1 -10 0"), std::string::npos)
      << svg;
  // X -30..10, Y -10..10, a 5% margin of the larger side (40), and room
  // for the scale below.
  EXPECT_NE(svg.find("viewBox=\"-32 -12 44 28\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">10 mm</text>"), std::string::npos) << svg;
}

TEST(SvgWriter, ArcsInOtherPlanesAreLinesThroughTheirPoints) {
  mbrt_motion arc = move(MBRT_MOTION_CW, 0, 0, 0, 0);
  arc.plane = 18;
  arc.center_axes[0] = 'Z';
  arc.center_axes[1] = 'X';
  arc.start[2] = 5;
  arc.end[0] = 5;
  arc.end[2] = 0; // a quarter from Z5 X0 to Z0 X5 about the origin
  const std::string svg = drawing({arc});
  EXPECT_NE(svg.find("L5 0\""), std::string::npos) << svg;
  EXPECT_EQ(svg.find(" A"), std::string::npos);
}

// Under cutter compensation the programmed contour is drawn beside the
// tool centre: a boss corner R5 with the tool 2 outside it.
TEST(SvgWriter, TheProgrammedContourBesideTheToolCentre) {
  mbrt_motion line = move(MBRT_MOTION_LINEAR, 0, 12, 10, 12);
  line.programmed[1] = 10; // the tool runs 2 above the programmed Y10
  mbrt_motion corner = move(MBRT_MOTION_CW, 10, 12, 17, 5);
  corner.center[0] = 10;
  corner.center[1] = 5;
  corner.programmed[0] = 15; // the programmed arc: radius 5
  corner.programmed[1] = 5;
  const std::string svg = drawing({line, corner});
  EXPECT_NE(svg.find("class=\"programmed\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("d=\"M0 -12L10 -10A5 5 0 0 1 15 -5\""), std::string::npos)
      << svg;
  EXPECT_NE(svg.find("A7 7 0 0 1 17 -5"), std::string::npos) << svg;
  // Without compensation there is no such path.
  EXPECT_EQ(drawing({move(MBRT_MOTION_LINEAR, 0, 0, 5, 0)}).find("programmed"),
            std::string::npos);
}

} // namespace
} // namespace mbc::driver
