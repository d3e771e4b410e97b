// The bounds a writer thread counts ahead of the drawings (svg_writer.h,
// html_writer.h growthBound): no move makes the drawing or the page grow
// by more, whatever came before it, in every view.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "runner/html_writer.h"
#include "runner/svg_writer.h"

namespace mbc::runner {
namespace {

mbrt_motion move(int kind, std::initializer_list<double> start,
                 std::initializer_list<double> end, int decimals = 3) {
  mbrt_motion m{};
  m.kind = kind;
  m.axis_count = 3;
  m.axis_names = "XYZ";
  m.plane = 17;
  m.center_axes[0] = 'X';
  m.center_axes[1] = 'Y';
  m.decimals = decimals;
  m.line = 1;
  m.program = "O1";
  m.file = "bound.nc";
  std::copy(start.begin(), start.end(), m.start);
  std::copy(end.begin(), end.end(), m.end);
  std::copy(end.begin(), end.end(), m.programmed);
  return m;
}

/// An arc about `center` in `plane` (17, 18, 19) from `start` to `end`.
mbrt_motion arc(int kind, int plane, std::initializer_list<double> start,
                std::initializer_list<double> end, double c0, double c1) {
  mbrt_motion m = move(kind, start, end);
  static constexpr char kAxes[3][2] = {{'X', 'Y'}, {'Z', 'X'}, {'Y', 'Z'}};
  m.plane = plane;
  m.center_axes[0] = kAxes[plane - 17][0];
  m.center_axes[1] = kAxes[plane - 17][1];
  m.center[0] = c0;
  m.center[1] = c1;
  return m;
}

/// Moves that grow each path the most: long numbers (the address's
/// largest, negative), arcs drawn as samples, full circles, plunges into
/// holes, the programmed contour beside the tool under compensation.
std::vector<mbrt_motion> hardMoves() {
  constexpr double kFar = -99999.9999;
  std::vector<mbrt_motion> moves{
      move(MBRT_MOTION_RAPID, {0, 0, 0}, {kFar, 0.1234, kFar}),
      move(MBRT_MOTION_LINEAR, {kFar, 0.1234, kFar}, {kFar, 0.1234, -kFar}),
      move(MBRT_MOTION_LINEAR, {1.2345, 2.3456, 10}, {1.2345, 2.3456, -3}),
      move(MBRT_MOTION_LINEAR, {1.2345, 2.3456, -3}, {1.2345, 2.3456, -7}),
      arc(MBRT_MOTION_CW, 17, {kFar, 0, -1}, {kFar, 0, -1}, 0, 0),
      arc(MBRT_MOTION_CCW, 17, {kFar, 0, 0}, {-kFar, 0, -kFar}, 0, 0),
      arc(MBRT_MOTION_CW, 18, {0, 0, kFar}, {kFar, 0, 0}, 0, 0),
      arc(MBRT_MOTION_CCW, 19, {0, kFar, 0}, {0, 0, kFar}, 0, 0),
      arc(MBRT_MOTION_CW, 19, {0, kFar, 0}, {0, kFar, 0}, -kFar, 0)};
  mbrt_motion compensated =
      arc(MBRT_MOTION_CCW, 17, {kFar, 0, 0}, {kFar, 0, 0}, 0, 0);
  compensated.programmed[0] = kFar / 2; // the contour inside the tool's
  moves.push_back(compensated);
  mbrt_motion beside = move(MBRT_MOTION_LINEAR, {kFar, 0, 0}, {0, kFar, 0});
  beside.programmed[0] = 0.5555;
  beside.programmed[1] = kFar;
  moves.push_back(beside);
  mbrt_motion lathe = arc(MBRT_MOTION_CW, 18, {0, 0, 0}, {0, 0, 0}, kFar, 0);
  lathe.axis_count = 2;
  lathe.axis_names = "XZ";
  lathe.diameter_mask = 1;
  lathe.start[0] = 2 * kFar;
  lathe.end[0] = 2 * kFar;
  lathe.programmed[0] = 2 * kFar;
  moves.push_back(lathe);
  return moves;
}

TEST(GrowthBound, NoMoveGrowsTheDrawingByMore) {
  const std::vector<mbrt_motion> moves = hardMoves();
  for (const SvgView view : {SvgView::Auto, SvgView::XY, SvgView::XZ,
                             SvgView::YZ, SvgView::ZX, SvgView::Iso}) {
    SvgWriter svg(view);
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t i = 0; i < moves.size(); ++i) {
        const std::size_t bound = SvgWriter::growthBound(moves[i]);
        EXPECT_LE(svg.add(moves[i]), bound)
            << "view " << static_cast<int>(view) << ", move " << i;
      }
    }
  }
}

TEST(GrowthBound, NoMoveGrowsThePageByMore) {
  HtmlWriter html;
  for (const mbrt_motion& m : hardMoves()) {
    EXPECT_LE(html.add(m), HtmlWriter::growthBound(m));
  }
}

TEST(GrowthBound, AFullCircleIsBoundedByItsSegments) {
  // A helix of one turn: the page draws it in segments, as many again for
  // its programmed contour.
  mbrt_motion helix = arc(MBRT_MOTION_CCW, 17, {10, 0, 0}, {10, 0, -5}, 0, 0);
  HtmlWriter html;
  const std::size_t grown = html.add(helix);
  EXPECT_LE(grown, HtmlWriter::growthBound(helix));
  EXPECT_GT(grown, 100u); // the bound is met by a circle's segments
}

} // namespace
} // namespace mbc::runner
