// The SVG of --svg. Points are workpiece X and Y with y negated (SVG's y
// goes down), so a counter-clockwise arc has sweep flag 0. Arcs outside the
// XY plane are drawn as short lines through points on them; the drawing's
// box takes every arc's extreme points.
#include "driver/svg_writer.h"

#include <mbc/number_text.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace mbc::driver {

namespace {

constexpr int kArcSamples = 64;

int axisNamed(const mbrt_motion& m, char letter) {
  for (int axis = 0; axis < m.axis_count; ++axis) {
    if (m.axis_names[axis] == letter) {
      return axis;
    }
  }
  return -1;
}

/// An arc's plane axes, radius, start angle and signed sweep.
struct Arc {
  int p = -1;
  int q = -1;
  double radius = 0.0;
  double begin = 0.0;
  double sweep = 0.0; // > 0 counter-clockwise
};

Arc arcOf(const mbrt_motion& m) {
  Arc arc;
  arc.p = axisNamed(m, m.center_axes[0]);
  arc.q = axisNamed(m, m.center_axes[1]);
  const double sx = m.start[arc.p] - m.center[0];
  const double sy = m.start[arc.q] - m.center[1];
  const double ex = m.end[arc.p] - m.center[0];
  const double ey = m.end[arc.q] - m.center[1];
  arc.radius = std::hypot(sx, sy);
  arc.begin = std::atan2(sy, sx);
  const bool ccw = m.kind == MBRT_MOTION_CCW;
  double sweep =
      ccw ? std::atan2(ey, ex) - arc.begin : arc.begin - std::atan2(ey, ex);
  constexpr double kTurn = 2.0 * std::numbers::pi;
  sweep = std::fmod(sweep + 2.0 * kTurn, kTurn);
  if (sweep < 1e-12) {
    sweep = kTurn; // start == end: a full circle
  }
  arc.sweep = ccw ? sweep : -sweep;
  return arc;
}

/// The point at fraction t of an arc: round in its plane, straight (helix)
/// on the other axes.
std::array<double, MBRT_MAX_AXES> arcPoint(const mbrt_motion& m, const Arc& arc,
                                           double t) {
  std::array<double, MBRT_MAX_AXES> point{};
  for (int axis = 0; axis < m.axis_count; ++axis) {
    point[axis] = m.start[axis] + t * (m.end[axis] - m.start[axis]);
  }
  const double angle = arc.begin + t * arc.sweep;
  point[arc.p] = m.center[0] + arc.radius * std::cos(angle);
  point[arc.q] = m.center[1] + arc.radius * std::sin(angle);
  return point;
}

/// Where an arc passes 0, 90, 180 or 270 degrees, as fractions of it.
std::vector<double> extremes(const Arc& arc) {
  std::vector<double> fractions;
  constexpr double kTurn = 2.0 * std::numbers::pi;
  for (int quarter = 0; quarter < 4; ++quarter) {
    const double angle = quarter * kTurn / 4.0;
    const double ahead = arc.sweep > 0 ? angle - arc.begin : arc.begin - angle;
    const double t =
        std::fmod(ahead + 2.0 * kTurn, kTurn) / std::fabs(arc.sweep);
    if (t <= 1.0) {
      fractions.push_back(t);
    }
  }
  return fractions;
}

std::string number(double value) {
  return trimmedFixed(value, 4);
}

/// 1, 2 or 5 times a power of ten, at most `limit`.
double niceLength(double limit) {
  const double power = std::pow(10.0, std::floor(std::log10(limit)));
  for (double step : {5.0, 2.0, 1.0}) {
    if (step * power <= limit) {
      return step * power;
    }
  }
  return power;
}

} // namespace

void SvgWriter::include(double x, double y) {
  minX_ = haveBox_ ? std::min(minX_, x) : x;
  maxX_ = haveBox_ ? std::max(maxX_, x) : x;
  minY_ = haveBox_ ? std::min(minY_, y) : y;
  maxY_ = haveBox_ ? std::max(maxY_, y) : y;
  haveBox_ = true;
}

void SvgWriter::moveTo(bool rapid, double x, double y) {
  std::string& path = rapid ? rapids_ : feeds_;
  Pen& pen = rapid ? rapidPen_ : feedPen_;
  if (!pen.open || pen.x != x || pen.y != y) {
    path += fmt::format("M{} {}", number(x), number(-y));
  }
  include(x, y);
}

std::size_t SvgWriter::add(const mbrt_motion& m) {
  const std::size_t before =
      rapids_.size() + feeds_.size() + programmed_.size();
  draw(m);
  return rapids_.size() + feeds_.size() + programmed_.size() - before;
}

void SvgWriter::drawProgrammed(const mbrt_motion& m, int x, int y) {
  const double px = m.programmed[x];
  const double py = m.programmed[y];
  if (!programmedPen_.open) {
    programmed_ +=
        fmt::format("M{} {}", number(m.start[x]), number(-m.start[y]));
    lowX_ = highX_ = m.start[x];
    lowY_ = highY_ = m.start[y];
  }
  compensated_ = compensated_ || px != m.end[x] || py != m.end[y];
  lowX_ = std::min(lowX_, px);
  highX_ = std::max(highX_, px);
  lowY_ = std::min(lowY_, py);
  highY_ = std::max(highY_, py);
  const bool arc = m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW;
  const Arc toolArc = arc ? arcOf(m) : Arc{};
  const bool flat = arc && toolArc.p == x && toolArc.q == y;
  const bool full = flat && std::fabs(toolArc.sweep) >= 2.0 * std::numbers::pi;
  const bool moves = programmedPen_.x != px || programmedPen_.y != py;
  if (flat && (moves || full)) {
    // The programmed arc has the tool arc's centre and turn.
    const double radius = std::hypot(px - m.center[0], py - m.center[1]);
    const double begin = std::atan2(programmedPen_.y - m.center[1],
                                    programmedPen_.x - m.center[0]);
    const double end = std::atan2(py - m.center[1], px - m.center[0]);
    constexpr double kTurn = 2.0 * std::numbers::pi;
    const double sweep = std::fmod(
        (toolArc.sweep > 0 ? end - begin : begin - end) + 2.0 * kTurn, kTurn);
    const int sweepFlag = toolArc.sweep > 0 ? 0 : 1;
    const std::string r = number(radius);
    if (full) {
      programmed_ += fmt::format("A{} {} 0 0 {} {} {}", r, r, sweepFlag,
                                 number(2.0 * m.center[0] - px),
                                 number(-(2.0 * m.center[1] - py)));
    }
    programmed_ +=
        fmt::format("A{} {} 0 {} {} {} {}", r, r,
                    static_cast<int>(!full && sweep > std::numbers::pi),
                    sweepFlag, number(px), number(-py));
  } else if (moves) {
    // Rapids are no part of the contour: the pen lifts.
    programmed_ +=
        fmt::format("{}{} {}", m.kind == MBRT_MOTION_RAPID ? 'M' : 'L',
                    number(px), number(-py));
  }
  programmedPen_ = {true, px, py};
}

void SvgWriter::draw(const mbrt_motion& m) {
  const int x = axisNamed(m, 'X');
  const int y = axisNamed(m, 'Y');
  if (x < 0 || y < 0) {
    return;
  }
  unit_ = m.decimals == 4 ? "inch" : "mm";
  drawProgrammed(m, x, y);
  const bool rapid = m.kind == MBRT_MOTION_RAPID;
  std::string& path = rapid ? rapids_ : feeds_;
  moveTo(rapid, m.start[x], m.start[y]);
  if (m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW) {
    const Arc arc = arcOf(m);
    const bool flat = arc.p == x && arc.q == y;
    for (const double t : extremes(arc)) {
      const auto point = arcPoint(m, arc, t);
      include(point[x], point[y]);
    }
    for (int i = 1; i <= kArcSamples; ++i) {
      const auto point = arcPoint(m, arc, static_cast<double>(i) / kArcSamples);
      include(point[x], point[y]);
      if (!flat) {
        path += fmt::format("L{} {}", number(point[x]), number(-point[y]));
      }
    }
    if (flat) {
      // SVG draws no full circle in one arc: two halves.
      const bool full = std::fabs(arc.sweep) >= 2.0 * std::numbers::pi;
      const int sweepFlag = arc.sweep > 0 ? 0 : 1;
      const std::string radius = number(arc.radius);
      if (full) {
        const auto half = arcPoint(m, arc, 0.5);
        path += fmt::format("A{} {} 0 0 {} {} {}", radius, radius, sweepFlag,
                            number(half[x]), number(-half[y]));
      }
      const int large = !full && std::fabs(arc.sweep) > std::numbers::pi;
      path += fmt::format("A{} {} 0 {} {} {} {}", radius, radius, large,
                          sweepFlag, number(m.end[x]), number(-m.end[y]));
    }
  } else {
    path += fmt::format("L{} {}", number(m.end[x]), number(-m.end[y]));
  }
  include(m.end[x], m.end[y]);
  Pen& pen = rapid ? rapidPen_ : feedPen_;
  pen = {true, m.end[x], m.end[y]};
}

std::string SvgWriter::document() const {
  // Under a pocket's tool path lies its outline: the box takes it too.
  const double minX = compensated_ ? std::min(minX_, lowX_) : minX_;
  const double maxX = compensated_ ? std::max(maxX_, highX_) : maxX_;
  const double minY = compensated_ ? std::min(minY_, lowY_) : minY_;
  const double maxY = compensated_ ? std::max(maxY_, highY_) : maxY_;
  const double width = maxX - minX;
  const double height = maxY - minY;
  const double size = std::max({width, height, 1.0});
  const double margin = size * 0.05;
  const double font = size * 0.025;
  const double bar = niceLength(size / 4.0);
  // The scale sits under the drawing: in SVG coordinates below -minY.
  const double barY = -minY + margin + font;
  const double left = minX - margin;
  const double top = -maxY - margin;
  const double viewWidth = width + 2.0 * margin;
  const double viewHeight = height + 3.0 * margin + 2.0 * font;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" "
      "width=\"800\" height=\"{}\">\n",
      number(left), number(top), number(viewWidth), number(viewHeight),
      number(800.0 * viewHeight / viewWidth));
  // Strokes and dashes in drawing units, one per pixel of the 800 wide
  // picture, so that every renderer draws them alike.
  const double pixel = viewWidth / 800.0;
  const std::string stroke =
      fmt::format("fill=\"none\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
                  number(1.2 * pixel));
  svg += fmt::format("<path class=\"rapid\" {} stroke=\"#888\" "
                     "stroke-dasharray=\"{} {}\" d=\"{}\"/>\n",
                     stroke, number(6.0 * pixel), number(4.0 * pixel), rapids_);
  if (compensated_) {
    // The programmed contour, thin, under the tool centre's path.
    svg += fmt::format("<path class=\"programmed\" fill=\"none\" "
                       "stroke-width=\"{}\" stroke=\"#d2691e\" "
                       "stroke-dasharray=\"{} {}\" d=\"{}\"/>\n",
                       number(0.8 * pixel), number(2.0 * pixel),
                       number(2.0 * pixel), programmed_);
  }
  svg += fmt::format("<path class=\"feed\" {} stroke=\"#0057b8\" d=\"{}\"/>\n",
                     stroke, feeds_);
  svg += fmt::format("<path class=\"scale\" {} stroke=\"#000\" "
                     "d=\"M{} {}v{}h{}v{}\"/>\n",
                     stroke, number(minX), number(barY - font * 0.3),
                     number(font * 0.3), number(bar), number(-font * 0.3));
  svg += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\" "
                     "font-family=\"sans-serif\">{} {}</text>\n",
                     number(minX + bar + font * 0.5), number(barY + font * 0.3),
                     number(font), number(bar), unit_);
  svg += "</svg>\n";
  return svg;
}

} // namespace mbc::driver
