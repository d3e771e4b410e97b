// `mbc run --svg`: the toolpath drawn in the XY plane of the workpiece
// coordinates, rapids dashed, feeds solid, XY arcs as arcs, with a scale;
// under cutter compensation the programmed contour beside the tool centre.
#pragma once

#include <mbc/runtime.h>

#include <string>

namespace mbc::driver {

class SvgWriter {
public:
  /// Records one move; returns the bytes the drawing grew by.
  std::size_t add(const mbrt_motion& m);

  /// The whole drawing; it fits the moves with a margin.
  std::string document() const;

private:
  void draw(const mbrt_motion& m);
  void drawProgrammed(const mbrt_motion& m, int x, int y);
  void include(double x, double y);
  void moveTo(bool rapid, double x, double y);

  /// Where a path's last segment ended.
  struct Pen {
    bool open = false;
    double x = 0.0;
    double y = 0.0;
  };

  std::string rapids_; // path data, SVG coordinates (y down)
  std::string feeds_;
  std::string programmed_; // the programmed points, drawn if compensated_
  Pen rapidPen_;
  Pen feedPen_;
  Pen programmedPen_;
  bool compensated_ = false; // a move's end is not its programmed point
  double lowX_ = 0, highX_ = 0, lowY_ = 0, highY_ = 0; // programmed box
  bool haveBox_ = false;
  double minX_ = 0, maxX_ = 0, minY_ = 0, maxY_ = 0;
  const char* unit_ = "mm";
};

} // namespace mbc::driver
