// `mbc run --svg`: the toolpath drawn in one view of the workpiece
// coordinates (XY, XZ, YZ or isometric): rapids dashed, feeds and arcs
// coloured by depth (a lathe's by diameter: light outside, dark towards
// the centre), the holes where the tool plunges marked with their depth, the
// work origin and its axes, a grid, a title, a legend and a scale; under cutter
// compensation, in the XY view, the programmed contour beside the tool centre.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mbc::runner {

/// Auto: ZX (Z right, X up: a lathe's picture) for a machine with X and Z
/// but no Y, XY otherwise, decided by the first move.
enum class SvgView { Auto, XY, XZ, YZ, ZX, Iso };

/// "xy", "xz", "yz", "zx" or "iso"; false for anything else.
bool parseSvgView(std::string_view text, SvgView& view);

class SvgWriter {
public:
  explicit SvgWriter(SvgView view = SvgView::Auto) : view_(view) {}

  /// Records one move; returns the bytes the drawing grew by.
  std::size_t add(const mbrt_motion& motion);

  /// The most bytes add() may return for `motion`, whatever was added
  /// before: a writer thread counts it ahead of the drawing
  /// (toolpath_thread.h).
  static std::size_t growthBound(const mbrt_motion& motion);

  /// The whole drawing under a title line; it fits the moves, the holes
  /// and the origin with a margin.
  std::string document(const std::string& title = "") const;

private:
  /// A point of the view: u to the right, v up.
  struct Point {
    double u = 0.0;
    double v = 0.0;
  };

  /// A feed move's path data and the depth it is coloured by: its lowest
  /// Z, or on a lathe its smallest X (as programmed, a diameter).
  struct Piece {
    double depth = 0.0;
    bool arc = false;
    std::string d;
  };

  /// Where the tool went down along Z alone: its top and its bottom, and
  /// every bottom the plunges there reached (a spot drill's and a drill's),
  /// in the order of the run.
  struct Hole {
    Point at; // the bottom, in the view
    double top = 0.0;
    double bottom = 0.0;
    std::vector<double> bottoms;
  };

  Point project(const double* point, const mbrt_motion& m) const;
  void drawRapid(Point start, Point end);
  void drawArc(const mbrt_motion& m, std::string& d);
  void drawProgrammed(const mbrt_motion& m, int x, int y);
  void recordHole(const mbrt_motion& m);
  void include(Point p);
  std::string legend(double x, double y, double font, double pixel) const;
  /// The highest and the lowest depth of the feeds (0 without feeds).
  double depthTop() const;
  double depthBottom() const;

  /// Where a path's last segment ended.
  struct Pen {
    bool open = false;
    double x = 0.0;
    double y = 0.0;
  };

  SvgView view_;
  std::string rapids_; // path data, SVG coordinates (y down)
  // The rapids drawn, by their ends in 0.0001 units: a retrace is drawn
  // once, or its dashes would fill each other's gaps and look like a feed.
  std::set<std::array<long long, 4>> rapidSegments_;
  std::vector<Piece> feeds_;
  std::map<std::pair<long long, long long>, Hole> holes_; // by X, Y in um

  /// The hole and the block of the last plunge.
  struct HoleBlock {
    std::pair<long long, long long> key;
    int line = 0;
    std::string program;

    bool operator==(const HoleBlock&) const = default;
  };

  std::optional<HoleBlock> lastHoleBlock_;
  std::string programmed_; // the programmed points, drawn if compensated_
  Pen programmedPen_;
  bool compensated_ = false; // a move's end is not its programmed point
  bool haveBox_ = false;
  double minU_ = 0, maxU_ = 0, minV_ = 0, maxV_ = 0;
  const char* unit_ = "mm";
  char depthAxis_ = 'Z'; // X on a lathe, whose cuts go deeper in X
};

} // namespace mbc::runner
