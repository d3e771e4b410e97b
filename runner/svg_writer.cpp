// The SVG of --svg. Points are the view's u and v in workpiece units with
// v negated (SVG's y goes down), so an arc that turns counter-clockwise in
// the view has sweep flag 0. Arcs whose plane is not the view's are drawn
// as short lines through points on them; the drawing's box takes every
// arc's extreme points.
#include "runner/svg_writer.h"

#include <mbc/number_text.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "runner/arc_geometry.h"
#include "runner/xml_text.h"

namespace mbc::runner {

namespace {

constexpr int kArcSamples = 64;

// The decimals of every number the drawing writes.
constexpr int kDecimals = 4;

std::string number(double value) {
  return trimmedFixed(value, kDecimals);
}

/// A path command to a point appended to path data ("L1.5 -2"), its
/// numbers as number() writes them: no string per number, as every move
/// draws one or two.
void appendPoint(std::string& d, char command, double u, double v) {
  d += command;
  appendTrimmedFixed(d, u, kDecimals);
  d += ' ';
  appendTrimmedFixed(d, v, kDecimals);
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

// The colours of feeds and arcs: light at the top of the cut, dark at its
// bottom.
struct Ramp {
  std::array<int, 3> light;
  std::array<int, 3> dark;

  std::string at(double t) const {
    std::array<int, 3> c{};
    for (int i = 0; i < 3; ++i) {
      c[i] = static_cast<int>(std::lround(light[i] + t * (dark[i] - light[i])));
    }
    return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
  }
};

constexpr Ramp kFeedRamp{{107, 174, 214}, {8, 48, 107}};
constexpr Ramp kArcRamp{{188, 155, 224}, {74, 20, 134}};
constexpr int kDepthLevels = 6;
// The shade of a cut at one depth, and of the legend's samples.
constexpr int kSingleDepthLevel = 3;

// The view's axis letters along u and v; none for the isometric view.
std::pair<char, char> viewAxes(SvgView view) {
  switch (view) {
    case SvgView::Auto: // no move to decide by
    case SvgView::XY:
      return {'X', 'Y'};
    case SvgView::XZ:
      return {'X', 'Z'};
    case SvgView::YZ:
      return {'Y', 'Z'};
    case SvgView::ZX:
      return {'Z', 'X'};
    case SvgView::Iso:
      break;
  }
  return {0, 0};
}

const char* viewName(SvgView view) {
  switch (view) {
    case SvgView::Auto:
    case SvgView::XY:
      return "XY";
    case SvgView::XZ:
      return "XZ";
    case SvgView::YZ:
      return "YZ";
    case SvgView::ZX:
      return "ZX";
    case SvgView::Iso:
      break;
  }
  return "isometric";
}

// X, Y and Z in the view: u right, v up. The isometric view looks from
// the front right above: X runs right and down, Y right and up, Z up.
std::pair<double, double> toView(SvgView view, double x, double y, double z) {
  switch (view) {
    case SvgView::Auto:
    case SvgView::XY:
      return {x, y};
    case SvgView::XZ:
      return {x, z};
    case SvgView::YZ:
      return {y, z};
    case SvgView::ZX:
      return {z, x};
    case SvgView::Iso:
      break;
  }
  const double c = std::cos(std::numbers::pi / 6.0);
  return {(x + y) * c, (y - x) * 0.5 + z};
}

// The mark of a hole: a ring with a cross, centred at (x, y) in SVG
// coordinates.
std::string holeMark(double x, double y, double font, double pixel) {
  const double r = 0.45 * font;
  return fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"#fff\" "
                     "stroke=\"#c0392b\" stroke-width=\"{}\"/>"
                     "<path d=\"M{} {}h{}M{} {}v{}\" stroke=\"#c0392b\" "
                     "stroke-width=\"{}\"/>",
                     number(x), number(y), number(r), number(1.2 * pixel),
                     number(x - r), number(y), number(2 * r), number(x),
                     number(y - r), number(2 * r), number(0.8 * pixel));
}

} // namespace

bool parseSvgView(std::string_view text, SvgView& view) {
  constexpr std::pair<std::string_view, SvgView> kViews[] = {
      {"xy", SvgView::XY},
      {"xz", SvgView::XZ},
      {"yz", SvgView::YZ},
      {"zx", SvgView::ZX},
      {"iso", SvgView::Iso}};
  for (const auto& [name, v] : kViews) {
    if (text == name) {
      view = v;
      return true;
    }
  }
  return false;
}

SvgWriter::Point SvgWriter::project(const double* point,
                                    const mbrt_motion& m) const {
  const int x = axisNamed(m, 'X');
  const int y = axisNamed(m, 'Y');
  const int z = axisNamed(m, 'Z');
  const auto [u, v] = toView(view_, x >= 0 ? point[x] : 0.0,
                             y >= 0 ? point[y] : 0.0, z >= 0 ? point[z] : 0.0);
  return {u, v};
}

void SvgWriter::include(Point p) {
  minU_ = haveBox_ ? std::min(minU_, p.u) : p.u;
  maxU_ = haveBox_ ? std::max(maxU_, p.u) : p.u;
  minV_ = haveBox_ ? std::min(minV_, p.v) : p.v;
  maxV_ = haveBox_ ? std::max(maxV_, p.v) : p.v;
  haveBox_ = true;
}

std::size_t SvgWriter::add(const mbrt_motion& motion) {
  const mbrt_motion m = motion.diameter_mask != 0 ? inRadii(motion) : motion;
  if (view_ == SvgView::Auto) {
    view_ = isLatheMotion(m) ? SvgView::ZX : SvgView::XY;
  }
  const std::size_t before = rapids_.size() + programmed_.size() +
                             feeds_.size() * sizeof(Piece) +
                             holes_.size() * sizeof(Hole);
  unit_ = m.decimals == 4 ? "inch" : "mm";
  const int x = axisNamed(m, 'X');
  const int y = axisNamed(m, 'Y');
  if (view_ == SvgView::XY && x >= 0 && y >= 0) {
    drawProgrammed(m, x, y);
  }
  const Point start = project(m.start, m);
  const Point end = project(m.end, m);
  include(start);
  include(end);
  std::size_t grown = 0;
  if (m.kind == MBRT_MOTION_RAPID) {
    drawRapid(start, end);
  } else {
    if (motion.diameter_mask != 0) {
      depthAxis_ = 'X';
    }
    const int deep = axisNamed(motion, depthAxis_);
    Piece piece;
    piece.depth =
        deep >= 0 ? std::min(motion.start[deep], motion.end[deep]) : 0.0;
    piece.arc = m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW;
    appendPoint(piece.d, 'M', start.u, -start.v);
    if (piece.arc) {
      drawArc(m, piece.d);
    } else {
      appendPoint(piece.d, 'L', end.u, -end.v);
      // A lathe turns along Z: no move of it is a hole.
      if (motion.diameter_mask == 0) {
        recordHole(m);
      }
    }
    grown = piece.d.size();
    feeds_.push_back(std::move(piece));
  }
  return rapids_.size() + programmed_.size() + feeds_.size() * sizeof(Piece) +
         holes_.size() * sizeof(Hole) + grown - before;
}

std::size_t SvgWriter::growthBound(const mbrt_motion& motion) {
  // Every number drawn is a coordinate of the move or of its arc's centre,
  // a point of the arc, a radius, or one of these projected (isometric) or
  // mirrored about the centre: within 16 times the largest coordinate.
  double largest =
      std::max(std::fabs(motion.center[0]), std::fabs(motion.center[1]));
  for (int axis = 0; axis < motion.axis_count; ++axis) {
    for (const double* point : {motion.start, motion.end, motion.programmed}) {
      largest = std::max(largest, std::fabs(point[axis]));
    }
  }
  // The tokens of the paths a move adds to, each a number or a flag after
  // its letter or space: the programmed contour's (a move to its start, a
  // full circle as two arcs of seven), a rapid's four, and a feed's (a move
  // to its start, then a line, two arcs, or the samples of an arc).
  constexpr std::size_t kTokens = 2 + 2 * 7 + 4 + 2 + 2 * kArcSamples;
  return kTokens * (trimmedFixedBound(16.0 * largest, kDecimals) + 1) +
         sizeof(Piece) + sizeof(Hole);
}

/// A rapid is a subpath of its own from its lower end, so that its dashes
/// start there: a retract and the plunge back share their dashes, and a
/// rapid drawn before is not drawn again.
void SvgWriter::drawRapid(Point start, Point end) {
  const auto key = [](Point p) {
    return std::pair{std::llround(p.u * 1e4), std::llround(p.v * 1e4)};
  };
  auto a = key(start), b = key(end);
  if (a == b) {
    return; // along the view's depth: nothing to draw
  }
  if (b < a) {
    std::swap(a, b);
    std::swap(start, end);
  }
  if (!rapidSegments_.insert({a.first, a.second, b.first, b.second}).second) {
    return;
  }
  appendPoint(rapids_, 'M', start.u, -start.v);
  appendPoint(rapids_, 'L', end.u, -end.v);
}

void SvgWriter::drawArc(const mbrt_motion& m, std::string& d) {
  const Arc arc = arcOf(m);
  const auto [uAxis, vAxis] = viewAxes(view_);
  // +1 when the arc's plane axes are the view's in order, -1 swapped (a
  // G18 arc in the XZ view turns the other way there), 0 not flat.
  const int turn = m.center_axes[0] == uAxis && m.center_axes[1] == vAxis   ? 1
                   : m.center_axes[0] == vAxis && m.center_axes[1] == uAxis ? -1
                                                                            : 0;
  const bool flat = turn != 0;
  for (const double t : extremes(arc)) {
    include(project(arcPoint(m, arc, t).data(), m));
  }
  for (int i = 1; i <= kArcSamples; ++i) {
    const Point p = project(
        arcPoint(m, arc, static_cast<double>(i) / kArcSamples).data(), m);
    include(p);
    if (!flat) {
      appendPoint(d, 'L', p.u, -p.v);
    }
  }
  if (!flat) {
    return;
  }
  // SVG draws no full circle in one arc: two halves.
  const bool full = std::fabs(arc.sweep) >= 2.0 * std::numbers::pi;
  const int sweepFlag = (arc.sweep > 0) == (turn > 0) ? 0 : 1;
  const std::string radius = number(arc.radius);
  if (full) {
    const Point half = project(arcPoint(m, arc, 0.5).data(), m);
    d += fmt::format("A{} {} 0 0 {} {} {}", radius, radius, sweepFlag,
                     number(half.u), number(-half.v));
  }
  const Point end = project(m.end, m);
  const int large = !full && std::fabs(arc.sweep) > std::numbers::pi;
  d += fmt::format("A{} {} 0 {} {} {} {}", radius, radius, large, sweepFlag,
                   number(end.u), number(-end.v));
}

void SvgWriter::recordHole(const mbrt_motion& m) {
  const int x = axisNamed(m, 'X');
  const int y = axisNamed(m, 'Y');
  const int z = axisNamed(m, 'Z');
  if (z < 0 || !(m.end[z] < m.start[z])) {
    return;
  }
  for (int axis = 0; axis < m.axis_count; ++axis) {
    if (axis != z && m.end[axis] != m.start[axis]) {
      return; // not along Z alone
    }
  }
  const double hx = x >= 0 ? m.end[x] : 0.0;
  const double hy = y >= 0 ? m.end[y] : 0.0;
  const std::pair<long long, long long> key{std::llround(hx * 1e3),
                                            std::llround(hy * 1e3)};
  const auto [it, added] = holes_.try_emplace(
      key, Hole{project(m.end, m), m.start[z], m.end[z], {}});
  Hole& hole = it->second;
  // The pecks of one block (G73, G83) go on down one hole: its depth is
  // the deepest. Another block's plunge (a drill after the spot drill) is
  // a depth of its own.
  HoleBlock block{key, m.line, m.program != nullptr ? m.program : ""};
  if (!added && lastHoleBlock_ == block) {
    hole.bottoms.back() = std::min(hole.bottoms.back(), m.end[z]);
  } else if (std::none_of(
                 hole.bottoms.begin(), hole.bottoms.end(),
                 [&](double b) { return std::fabs(b - m.end[z]) < 1e-9; })) {
    hole.bottoms.push_back(m.end[z]);
  }
  lastHoleBlock_ = std::move(block);
  if (!added) {
    hole.top = std::max(hole.top, m.start[z]);
    if (m.end[z] < hole.bottom) {
      hole.bottom = m.end[z];
      hole.at = project(m.end, m);
    }
  }
}

void SvgWriter::drawProgrammed(const mbrt_motion& m, int x, int y) {
  const double px = m.programmed[x];
  const double py = m.programmed[y];
  if (!programmedPen_.open) {
    appendPoint(programmed_, 'M', m.start[x], -m.start[y]);
  }
  compensated_ = compensated_ || px != m.end[x] || py != m.end[y];
  // Under a pocket's tool path lies its outline: the box takes it too.
  include({px, py});
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
    appendPoint(programmed_, m.kind == MBRT_MOTION_RAPID ? 'M' : 'L', px, -py);
  }
  programmedPen_ = {true, px, py};
}

double SvgWriter::depthTop() const {
  double top = feeds_.empty() ? 0.0 : feeds_.front().depth;
  for (const Piece& p : feeds_) {
    top = std::max(top, p.depth);
  }
  return top;
}

double SvgWriter::depthBottom() const {
  double bottom = feeds_.empty() ? 0.0 : feeds_.front().depth;
  for (const Piece& p : feeds_) {
    bottom = std::min(bottom, p.depth);
  }
  return bottom;
}

std::string SvgWriter::legend(double x, double y, double font,
                              double pixel) const {
  // Each entry: a sample 2 fonts long, its name, a gap.
  const auto advance = [font](std::string_view name) {
    return font * (2.6 + 0.55 * static_cast<double>(name.size()) + 1.0);
  };
  const auto label = [&](double at, std::string_view name) {
    return fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\">{}</text>",
                       number(at + 2.4 * font), number(y + 0.35 * font),
                       number(0.8 * font), name);
  };
  const std::string width = number(1.6 * pixel);
  std::string out = "<g class=\"legend\" font-family=\"sans-serif\">";
  out +=
      fmt::format("<path d=\"M{} {}h{}\" stroke=\"#888\" stroke-width=\"{}\" "
                  "stroke-dasharray=\"{} {}\"/>",
                  number(x), number(y), number(2 * font), width,
                  number(6 * pixel), number(4 * pixel)) +
      label(x, "rapid");
  x += advance("rapid");
  out += fmt::format(
             "<path d=\"M{} {}h{}\" stroke=\"{}\" stroke-width=\"{}\"/>",
             number(x), number(y), number(2 * font),
             kFeedRamp.at(kSingleDepthLevel / (kDepthLevels - 1.0)), width) +
         label(x, "feed");
  x += advance("feed");
  out += fmt::format("<path d=\"M{} {}a{} {} 0 0 1 {} 0\" fill=\"none\" "
                     "stroke=\"{}\" stroke-width=\"{}\"/>",
                     number(x), number(y + 0.4 * font), number(font),
                     number(font), number(2 * font),
                     kArcRamp.at(kSingleDepthLevel / (kDepthLevels - 1.0)),
                     width) +
         label(x, "arc");
  x += advance("arc");
  if (depthAxis_ == 'Z') { // a lathe has no holes
    out += holeMark(x + font, y, font, pixel) + label(x, "plunge, depth");
    x += advance("plunge, depth");
  }
  // The depth scale: its top and bottom, the colours between.
  const double top = depthTop(), bottom = depthBottom();
  out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\">{} {}</text>",
                     number(x), number(y + 0.35 * font), number(0.8 * font),
                     depthAxis_, number(top));
  x += font * (1.5 + 0.45 * static_cast<double>(number(top).size()));
  // A cut at one depth has one colour: one swatch and no bottom.
  const bool oneDepth = top - bottom <= 1e-9;
  for (int k = oneDepth ? kSingleDepthLevel : 0;
       k < (oneDepth ? kSingleDepthLevel + 1 : kDepthLevels); ++k) {
    out +=
        fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" "
                    "fill=\"{}\"/>",
                    number(x), number(y - 0.4 * font), number(0.8 * font),
                    number(0.8 * font), kFeedRamp.at(k / (kDepthLevels - 1.0)));
    x += 0.8 * font;
  }
  if (!oneDepth) {
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\">{}</text>",
                       number(x + 0.4 * font), number(y + 0.35 * font),
                       number(0.8 * font), number(bottom));
  }
  return out + "</g>\n";
}

std::string SvgWriter::document(const std::string& title) const {
  // The work origin and its axes are part of the picture.
  const double anyU = haveBox_ ? minU_ : 0.0, anyV = haveBox_ ? minV_ : 0.0;
  double minU = std::min(anyU, 0.0), maxU = std::max(haveBox_ ? maxU_ : 0, 0.0);
  double minV = std::min(anyV, 0.0), maxV = std::max(haveBox_ ? maxV_ : 0, 0.0);
  const double axisLength =
      niceLength(std::max({maxU - minU, maxV - minV, 1.0}) / 8.0);
  std::string axes;
  const char* names = "XYZ";
  const char* colors[] = {"#d62728", "#2ca02c", "#1f77b4"};
  std::vector<std::pair<int, Point>> tips;
  for (int axis = 0; axis < 3; ++axis) {
    const auto [u, v] =
        toView(view_, axis == 0 ? axisLength : 0.0,
               axis == 1 ? axisLength : 0.0, axis == 2 ? axisLength : 0.0);
    if (std::hypot(u, v) > axisLength * 1e-6) {
      tips.push_back({axis, {u, v}});
      minU = std::min(minU, u);
      maxU = std::max(maxU, u);
      minV = std::min(minV, v);
      maxV = std::max(maxV, v);
    }
  }
  const double width = maxU - minU;
  const double height = maxV - minV;
  const double size = std::max({width, height, 1.0});
  const double margin = size * 0.05;
  const double font = size * 0.025;
  const double titleBand = 2.0 * font;
  const double legendBand = 4.5 * font;
  const double left = minU - margin;
  const double top = -maxV - margin - titleBand;
  const double viewWidth = size + 2.0 * margin;
  const double viewHeight = height + 2.0 * margin + titleBand + legendBand;
  // Strokes and dashes in drawing units, one per pixel of the 800 wide
  // picture, so that every renderer draws them alike.
  const double pixel = viewWidth / 800.0;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" "
      "width=\"800\" height=\"{}\">\n",
      number(left), number(top), number(viewWidth), number(viewHeight),
      number(800.0 * viewHeight / viewWidth));
  svg += fmt::format("<rect class=\"paper\" x=\"{}\" y=\"{}\" width=\"{}\" "
                     "height=\"{}\" fill=\"#fff\"/>\n",
                     number(left), number(top), number(viewWidth),
                     number(viewHeight));
  // The grid: lines at a round spacing over the drawing.
  const double spacing = niceLength(size / 8.0);
  std::string grid;
  for (double u = std::ceil(minU / spacing) * spacing; u <= maxU + 1e-9;
       u += spacing) {
    grid += fmt::format("M{} {}V{}", number(u), number(-maxV), number(-minV));
  }
  for (double v = std::ceil(minV / spacing) * spacing; v <= maxV + 1e-9;
       v += spacing) {
    grid += fmt::format("M{} {}H{}", number(minU), number(-v), number(maxU));
  }
  svg += fmt::format("<path class=\"grid\" fill=\"none\" stroke=\"#e4e4e4\" "
                     "stroke-width=\"{}\" d=\"{}\"/>\n",
                     number(0.8 * pixel), grid);
  const std::string stroke =
      fmt::format("fill=\"none\" stroke-width=\"{}\" stroke-linejoin=\"round\" "
                  "stroke-linecap=\"round\"",
                  number(1.4 * pixel));
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
  // Feeds and arcs by depth: one path per colour, the deepest drawn last.
  const double depthTopZ = depthTop(), depthBottomZ = depthBottom();
  const double range = depthTopZ - depthBottomZ;
  for (int arc = 0; arc < 2; ++arc) {
    std::array<std::string, kDepthLevels> levels;
    for (const Piece& p : feeds_) {
      if (p.arc == (arc == 1)) {
        const int k =
            range > 1e-9
                ? static_cast<int>(std::lround((depthTopZ - p.depth) / range *
                                               (kDepthLevels - 1)))
                : kSingleDepthLevel;
        levels[static_cast<std::size_t>(k)] += p.d;
      }
    }
    for (int k = 0; k < kDepthLevels; ++k) {
      const std::string& d = levels[static_cast<std::size_t>(k)];
      if (!d.empty()) {
        svg += fmt::format(
            "<path class=\"{}\" {} stroke=\"{}\" d=\"{}\"/>\n",
            arc ? "arc" : "feed", stroke,
            (arc ? kArcRamp : kFeedRamp).at(k / (kDepthLevels - 1.0)), d);
      }
    }
  }
  // The holes, with their depths while there are few enough to read; a
  // label that would run past the right edge goes left of its hole.
  const bool labelled = holes_.size() <= 60;
  const double right = left + viewWidth;
  for (const auto& [key, hole] : holes_) {
    svg += "<g class=\"hole\">" + holeMark(hole.at.u, -hole.at.v, font, pixel);
    if (labelled) {
      std::string text;
      for (const double b : hole.bottoms) {
        text += (text.empty() ? "Z" : " / Z") + number(b);
      }
      // Sans-serif digits are about 0.6 of the font size wide.
      const double textSize = 0.7 * font;
      const double wide = 0.6 * textSize * static_cast<double>(text.size());
      const bool leftOf = hole.at.u + 0.6 * font + wide > right;
      svg += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\" "
                         "font-family=\"sans-serif\" fill=\"#a02020\"{}>{}"
                         "</text>",
                         number(hole.at.u + (leftOf ? -0.6 : 0.6) * font),
                         number(-hole.at.v - 0.6 * font), number(textSize),
                         leftOf ? " text-anchor=\"end\"" : "", text);
    }
    svg += "</g>\n";
  }
  // The work origin and its axes.
  svg += "<g class=\"axes\" font-family=\"sans-serif\">";
  for (const auto& [axis, tip] : tips) {
    // An arrowhead at the tip: back along the axis, out to either side.
    const double length = std::hypot(tip.u, tip.v);
    const double du = tip.u / length, dv = -tip.v / length;
    const double backU = tip.u - 0.6 * font * du;
    const double backV = -tip.v - 0.6 * font * dv;
    svg += fmt::format(
        "<path d=\"M0 0L{} {}\" stroke=\"{}\" stroke-width=\"{}\"/>"
        "<path d=\"M{} {}L{} {}L{} {}Z\" fill=\"{}\"/>"
        "<text x=\"{}\" y=\"{}\" font-size=\"{}\" fill=\"{}\">{}</text>",
        number(tip.u), number(-tip.v), colors[axis], number(1.6 * pixel),
        number(tip.u), number(-tip.v), number(backU - 0.25 * font * dv),
        number(backV + 0.25 * font * du), number(backU + 0.25 * font * dv),
        number(backV - 0.25 * font * du), colors[axis],
        number(tip.u + 0.3 * font), number(-tip.v - 0.3 * font),
        number(0.8 * font), colors[axis], names[axis]);
  }
  svg += fmt::format("<circle cx=\"0\" cy=\"0\" r=\"{}\" fill=\"#000\"/></g>\n",
                     number(3.0 * pixel));
  svg += fmt::format(
      "<text class=\"title\" x=\"{}\" y=\"{}\" font-size=\"{}\" "
      "font-family=\"sans-serif\" font-weight=\"bold\">{}</text>\n",
      number(left + margin), number(top + 1.3 * font), number(0.9 * font),
      xmlEscaped(title.empty() ? std::string("toolpath") : title));
  // Under the drawing: the legend, then the scale and the view.
  const double legendY = -minV + margin + 1.2 * font;
  svg += legend(minU, legendY, font, pixel);
  const double barY = legendY + 2.2 * font;
  const double bar = niceLength(size / 4.0);
  svg += fmt::format("<path class=\"scale\" {} stroke=\"#000\" "
                     "d=\"M{} {}v{}h{}v{}\"/>\n",
                     stroke, number(minU), number(barY - font * 0.3),
                     number(font * 0.3), number(bar), number(-font * 0.3));
  svg += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\" "
                     "font-family=\"sans-serif\">{} {}; view {}</text>\n",
                     number(minU + bar + font * 0.5), number(barY + font * 0.3),
                     number(0.8 * font), number(bar), unit_, viewName(view_));
  svg += "</svg>\n";
  return svg;
}

} // namespace mbc::runner
