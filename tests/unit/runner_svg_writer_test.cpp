// --svg (runner/svg_writer.cpp): path data for lines and arcs in each view,
// the box that holds every arc and the origin, holes, depth colours, the
// axes and the scale.
#include <gtest/gtest.h>

#include <string>

#include "runner/svg_writer.h"

namespace mbc::runner {
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

std::string drawing(std::initializer_list<mbrt_motion> moves,
                    SvgView view = SvgView::XY) {
  SvgWriter svg(view);
  for (const mbrt_motion& m : moves) {
    svg.add(m);
  }
  return svg.document("O1 \"test\" <1>");
}

TEST(SvgWriter, RapidsDashedFeedsSolidTitled) {
  const std::string svg = drawing({move(MBRT_MOTION_RAPID, 0, 0, 10, 0),
                                   move(MBRT_MOTION_LINEAR, 10, 0, 10, 5),
                                   move(MBRT_MOTION_LINEAR, 10, 5, 0, 5),
                                   move(MBRT_MOTION_RAPID, 0, 5, 0, 0)});
  EXPECT_NE(svg.find("class=\"rapid\""), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  // Each rapid from its lower end: its dashes start there.
  EXPECT_NE(svg.find("d=\"M0 0L10 0M0 0L0 -5\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("d=\"M10 0L10 -5M10 -5L0 -5\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">O1 \"test\" &lt;1&gt;</text>"), std::string::npos)
      << svg;
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
  // X -30..10, Y -10..10 (the origin and its axes 5 long inside), a 5%
  // margin of the larger side (40), a title band (2 fonts of 1) above and
  // the legend and the scale (4.5 fonts) below.
  EXPECT_NE(svg.find("viewBox=\"-32 -14 44 30.5\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">10 mm; view XY</text>"), std::string::npos) << svg;
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
  // In the XZ view it is an arc: G18's Z, X is the view's X, Z swapped, so
  // three quarters clockwise about Y turn counter-clockwise there.
  const std::string side = drawing({arc}, SvgView::XZ);
  EXPECT_NE(side.find("M0 -5A5 5 0 1 0 5 0\""), std::string::npos) << side;
}

TEST(SvgWriter, PlungesAreHolesWithTheirDepth) {
  mbrt_motion down = move(MBRT_MOTION_LINEAR, 10, 5, 10, 5);
  down.start[2] = 2;
  down.end[2] = -3;
  mbrt_motion peck = down;
  peck.start[2] = -3;
  peck.end[2] = -8;
  mbrt_motion other = move(MBRT_MOTION_LINEAR, 20, 5, 20, 5);
  other.start[2] = 2;
  other.end[2] = -4;
  mbrt_motion slanted = move(MBRT_MOTION_LINEAR, 0, 0, 1, 0);
  slanted.end[2] = -1;
  const std::string svg = drawing({down, peck, other, slanted});
  std::size_t holes = 0;
  for (std::size_t at = svg.find("class=\"hole\""); at != std::string::npos;
       at = svg.find("class=\"hole\"", at + 1)) {
    ++holes;
  }
  EXPECT_EQ(holes, 2u) << svg;
  EXPECT_NE(svg.find(">Z-8</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">Z-4</text>"), std::string::npos) << svg;
  // The pecks of one block are one depth; another block's plunge into the
  // same hole (the drill after the spot drill) is a depth of its own.
  mbrt_motion drill = other;
  drill.end[2] = -12;
  drill.line = 7;
  const std::string both = drawing({down, peck, other, drill});
  EXPECT_NE(both.find(">Z-8</text>"), std::string::npos) << both;
  EXPECT_NE(both.find(">Z-4 / Z-12</text>"), std::string::npos) << both;
}

TEST(SvgWriter, FeedsColouredByDepthAndTheAxesOfTheView) {
  mbrt_motion high = move(MBRT_MOTION_LINEAR, 0, 0, 10, 0);
  mbrt_motion low = move(MBRT_MOTION_LINEAR, 10, 0, 10, 10);
  low.start[2] = low.end[2] = -10;
  const std::string top = drawing({high, low});
  EXPECT_NE(top.find("stroke=\"#6baed6\" d=\"M0 0L10 0\""), std::string::npos)
      << top;
  EXPECT_NE(top.find("stroke=\"#08306b\" d=\"M10 0L10 -10\""),
            std::string::npos)
      << top;
  EXPECT_NE(top.find(">X</text>"), std::string::npos);
  EXPECT_NE(top.find(">Y</text>"), std::string::npos);
  EXPECT_EQ(top.find(">Z</text>"), std::string::npos);
  const std::string side = drawing({high, low}, SvgView::XZ);
  EXPECT_EQ(side.find(">Y</text>"), std::string::npos);
  EXPECT_NE(side.find(">Z</text>"), std::string::npos);
  EXPECT_NE(side.find("view XZ"), std::string::npos);
  const std::string iso = drawing({high, low}, SvgView::Iso);
  for (const char* axis : {">X</text>", ">Y</text>", ">Z</text>"}) {
    EXPECT_NE(iso.find(axis), std::string::npos) << axis;
  }
  SvgView view = SvgView::XY;
  EXPECT_TRUE(parseSvgView("iso", view));
  EXPECT_EQ(view, SvgView::Iso);
  EXPECT_FALSE(parseSvgView("top", view));
}

// A lathe (X and Z, X a diameter) is drawn by default in the ZX view, Z to
// the right and X up, at its radii: a clockwise quarter circle of radius 5
// from X10 (radius 5) Z0 to X20 Z-5 about X20 Z0 stays a quarter circle
// (drawn at the diameters it would span 270 degrees of an ellipse).
TEST(SvgWriter, ALatheInZxAtItsRadii) {
  mbrt_motion arc{};
  arc.kind = MBRT_MOTION_CW;
  arc.axis_count = 2;
  arc.axis_names = "XZ";
  arc.diameter_mask = 1;
  arc.start[0] = 10;
  arc.end[0] = 20;
  arc.end[1] = -5;
  arc.plane = 18;
  arc.center_axes[0] = 'Z';
  arc.center_axes[1] = 'X';
  arc.center[0] = 0;
  arc.center[1] = 20;
  arc.decimals = 3;
  const std::string lathe = drawing({arc}, SvgView::Auto);
  EXPECT_NE(lathe.find("view ZX"), std::string::npos) << lathe;
  EXPECT_NE(lathe.find("d=\"M0 -5A5 5 0 0 "), std::string::npos) << lathe;
  EXPECT_NE(lathe.find(" -5 -10\""), std::string::npos) << lathe;
  // Coloured by diameter: the legend's scale is in X, without holes.
  EXPECT_NE(lathe.find(">X 10</text>"), std::string::npos) << lathe;
  EXPECT_EQ(lathe.find("plunge"), std::string::npos) << lathe;
  mbrt_motion outer = arc;
  outer.kind = MBRT_MOTION_LINEAR;
  outer.start[0] = outer.end[0] = 40;
  outer.start[1] = 0;
  outer.end[1] = -30;
  mbrt_motion inner = outer;
  inner.start[0] = inner.end[0] = 30;
  const std::string cuts = drawing({outer, inner}, SvgView::Auto);
  EXPECT_NE(cuts.find(">X 40</text>"), std::string::npos) << cuts;
  EXPECT_NE(cuts.find(">30</text>"), std::string::npos) << cuts;
  EXPECT_EQ(drawing({move(MBRT_MOTION_LINEAR, 0, 0, 1, 1)}, SvgView::Auto)
                .find("view ZX"),
            std::string::npos);
  SvgView view = SvgView::XY;
  EXPECT_TRUE(parseSvgView("zx", view));
  EXPECT_EQ(view, SvgView::ZX);
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
} // namespace mbc::runner
