// G71/G72 type II: roughing a shape with pockets (lathe_roughing.h).
//
// FANUC's own description was not at hand; the order follows what Haas's
// FANUC mode, the Rockwell 9/Series and LinuxCNC's interp_g7x.cc agree on
// (../shared/research/g71-type-ii.md): the cuts go level by level, Δd
// apart, from A's level towards the shape; each cut runs along its level to
// where the shape rises through it, follows the shape up to the level
// before and escapes e at 45 degrees; a pocket is cut to its bottom before
// the next, the tool entering each level along the shape at the cutting
// feed and leaving a finished pocket along the shape, over the rise to the
// next pocket. Then, as in type I, one pass along the shape leaving the
// allowance. The moves between cuts are reconstructed, not FANUC's.
//
// The work is done in a frame where the stock lies above the shape (h
// grows away from it) and the cuts run towards growing t: h is x (a
// radius) or -x, t is z or -z, both counts.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "lathe_roughing.h"
#include "shape_geometry.h"

namespace mbc::rt {

namespace {

constexpr double kPi = std::numbers::pi;

/// How far along an arc of `sweep` from `begin` the angle `angle` lies.
double travelTo(double angle, double begin, double sweep) {
  constexpr double kTurn = 2.0 * kPi;
  const double travel = sweep > 0.0 ? angle - begin : begin - angle;
  return std::fmod(std::fmod(travel, kTurn) + kTurn, kTurn);
}

/// The frame's signs: h = sx * x, t = dz * z (its own inverse).
struct Frame {
  double sx;
  double dz;

  ShapePoint map(ShapePoint p) const { return {sx * p.x, dz * p.z}; }

  ShapeMove map(ShapeMove move) const {
    move.end = map(move.end);
    move.center = map(move.center);
    if ((sx < 0.0) != (dz < 0.0)) {
      move.motion = mirrored(move.motion);
    }
    return move;
  }
};

/// A move of the shape with the point it starts from.
struct Piece {
  ShapePoint from;
  ShapeMove move;
};

/// A point of the shape: on piece `piece` (-1: before the shape, on the
/// free side of its start, where the cuts start).
struct Crossing {
  int piece = -1;
  ShapePoint at;
};

/// Where a level's cut can run: above the shape from `left` to `right`.
struct Span {
  Crossing left;
  Crossing right;
};

/// The points of a piece at height h, in the order the piece meets them.
std::vector<ShapePoint> pointsAt(const Piece& piece, double h) {
  const ShapePoint a = piece.from;
  const ShapePoint b = piece.move.end;
  if (!isArc(piece.move)) {
    if ((a.x - h) * (b.x - h) >= 0.0 || a.x == b.x) {
      return {};
    }
    return {{h, a.z + (h - a.x) * (b.z - a.z) / (b.x - a.x)}};
  }
  const ShapePoint c = piece.move.center;
  const double r = std::hypot(a.x - c.x, a.z - c.z);
  const double dx = h - c.x;
  if (std::fabs(dx) >= r) {
    return {};
  }
  const double begin = angleOf(a, c);
  const double sweep = sweepOf(piece.move, a);
  std::vector<std::pair<double, ShapePoint>> found;
  const double dzRoot = std::sqrt(r * r - dx * dx);
  for (const double z : {c.z + dzRoot, c.z - dzRoot}) {
    const ShapePoint p{h, z};
    const double angle = angleOf(p, c);
    if (onArc(angle, begin, sweep)) {
      found.emplace_back(travelTo(angle, begin, sweep), p);
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& p, const auto& q) { return p.first < q.first; });
  std::vector<ShapePoint> points;
  for (const auto& [travel, p] : found) {
    points.push_back(p);
  }
  return points;
}

/// The point halfway along a piece between two of its points.
ShapePoint between(const Piece& piece, ShapePoint p, ShapePoint q) {
  if (!isArc(piece.move)) {
    return {(p.x + q.x) / 2.0, (p.z + q.z) / 2.0};
  }
  const ShapePoint c = piece.move.center;
  const double r = std::hypot(p.x - c.x, p.z - c.z);
  ShapeMove part = piece.move;
  part.end = q;
  const double angle = angleOf(p, c) + sweepOf(part, p) / 2.0;
  return {c.x + r * std::sin(angle), c.z + r * std::cos(angle)};
}

class PocketRoughing {
public:
  PocketRoughing(const Shape& shape, const Roughing& roughing,
                 std::vector<ShapeMove>& out)
      : roughing_(roughing), out_(out) {
    const ShapeMove& first = shape.moves.front();
    const ShapePoint startC = shifted(first.end, roughing.allowance);
    ShapePoint endC = startC;
    for (std::size_t i = 1; i < shape.moves.size(); ++i) {
      endC = shifted(shape.moves[i].end, roughing.allowance);
    }
    frame_ = {shape.start.x >= startC.x ? 1.0 : -1.0,
              endC.z <= shape.start.z ? -1.0 : 1.0};
    a_ = frame_.map(shape.start);
    start_ = frame_.map(startC);
    ShapePoint from = start_;
    for (std::size_t i = 1; i < shape.moves.size(); ++i) {
      ShapeMove move = shape.moves[i];
      move.end = shifted(move.end, roughing.allowance);
      move.center = shifted(move.center, roughing.allowance);
      move = frame_.map(move);
      pieces_.push_back({from, move});
      from = move.end;
    }
    approach_ = first.motion == ShapeMotion::Rapid ? ShapeMotion::Rapid
                                                   : ShapeMotion::Line;
  }

  ShapeFault run();

private:
  bool alongT() const;
  std::vector<Span> spansAt(double h) const;
  void emit(ShapeMotion motion, ShapePoint to);
  void follow(const Crossing& from, const Crossing& to);
  Crossing climb(const Crossing& from, double limit);
  void backToA(double e);
  void cutBelow(const Span& span, double level, double aboveLevel);
  void enterFirst(const Span& outer, double outerLevel, const Span& span,
                  double level);

  double level(int k) const { return a_.x - k * roughing_.depth; }

  Crossing end() const {
    return {static_cast<int>(pieces_.size()) - 1, pieces_.back().move.end};
  }

  const Roughing& roughing_;
  std::vector<ShapeMove>& out_;
  Frame frame_{1.0, 1.0};
  ShapePoint a_;
  ShapePoint start_;
  std::vector<Piece> pieces_;
  ShapeMotion approach_ = ShapeMotion::Line;
  int levels_ = 0;
  Crossing last_; // where the last cut left the tool, on the shape
};

/// t never turns back along the shape (arcs by their extremes).
bool PocketRoughing::alongT() const {
  for (const Piece& piece : pieces_) {
    if (piece.move.end.z < piece.from.z) {
      return false;
    }
    if (isArc(piece.move)) {
      const ShapePoint c = piece.move.center;
      const double begin = angleOf(piece.from, c);
      const double sweep = sweepOf(piece.move, piece.from);
      const double reach = std::fabs(sweep);
      for (const double extreme : {0.0, kPi}) { // where t turns
        const double travel = travelTo(extreme, begin, sweep);
        if (travel > 1e-9 && travel < reach - 1e-9) {
          return false;
        }
      }
    }
  }
  return true;
}

/// The spans of the cut at height h: where the shape lies below it, the
/// first one from the free side of the shape's start when the start lies
/// below.
std::vector<Span> PocketRoughing::spansAt(double h) const {
  std::vector<Span> spans;
  bool below = start_.x < h;
  Span open{{-1, {h, a_.z}}, {}};
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const Piece& piece = pieces_[i];
    std::vector<ShapePoint> points{piece.from};
    for (const ShapePoint& p : pointsAt(piece, h)) {
      points.push_back(p);
    }
    points.push_back(piece.move.end);
    for (std::size_t j = 0; j + 1 < points.size(); ++j) {
      const bool now = between(piece, points[j], points[j + 1]).x < h;
      if (now == below) {
        continue;
      }
      const Crossing at{static_cast<int>(i), {h, points[j].z}};
      if (now) {
        open.left = at;
      } else {
        open.right = at;
        spans.push_back(open);
      }
      below = now;
    }
  }
  if (below) { // the shape ends below the level: the cut runs to its end
    open.right = {static_cast<int>(pieces_.size()) - 1,
                  {h, pieces_.back().move.end.z}};
    spans.push_back(open);
  }
  return spans;
}

void PocketRoughing::emit(ShapeMotion motion, ShapePoint to) {
  out_.push_back(frame_.map(straightTo(motion, to)));
}

/// Along the shape at the cutting feed, from one of its points to a later
/// one.
void PocketRoughing::follow(const Crossing& from, const Crossing& to) {
  ShapePoint at = from.at;
  for (int i = std::max(from.piece, 0); i <= to.piece; ++i) {
    ShapeMove move = pieces_[static_cast<std::size_t>(i)].move;
    if (i == to.piece) {
      move.end = to.at;
    }
    if (move.end.x == at.x && move.end.z == at.z) {
      continue;
    }
    if (move.motion == ShapeMotion::Rapid) {
      move.motion = ShapeMotion::Line;
    }
    move.feed = 0.0;
    out_.push_back(frame_.map(move));
    at = move.end;
  }
}

/// Up the shape from where a cut ended, as long as it rises, to the height
/// `limit` at the most: where the escape starts.
Crossing PocketRoughing::climb(const Crossing& from, double limit) {
  Crossing at = from;
  for (int i = std::max(from.piece, 0); i < static_cast<int>(pieces_.size());
       ++i) {
    const Piece& piece = pieces_[static_cast<std::size_t>(i)];
    const ShapePoint end = piece.move.end;
    bool rises = end.x > at.at.x;
    if (rises && isArc(piece.move)) { // no top inside the arc
      const ShapePoint c = piece.move.center;
      ShapeMove rest = piece.move;
      const double sweep = sweepOf(rest, at.at);
      const double travel = travelTo(kPi / 2.0, angleOf(at.at, c), sweep);
      rises = travel <= 1e-9 || travel >= std::fabs(sweep) - 1e-9;
    }
    if (!rises) {
      break;
    }
    Crossing to{i, end};
    if (end.x >= limit) {
      const std::vector<ShapePoint> top = pointsAt({at.at, piece.move}, limit);
      to.at = top.empty() ? end : top.front();
    }
    follow(at, to);
    at = to;
    if (at.at.x >= limit) {
      break;
    }
  }
  return at;
}

/// The tool is at the left of `span`: its cut, then the spans below it in
/// order, each pocket to its bottom. After a cut with more below it the
/// tool climbs the shape towards the level before, `aboveLevel`, and
/// escapes.
void PocketRoughing::cutBelow(const Span& span, double h, double aboveLevel) {
  emit(ShapeMotion::Line, span.right.at);
  last_ = span.right;
  const int k = static_cast<int>(std::lround((a_.x - h) / roughing_.depth));
  if (k >= levels_) {
    return;
  }
  const double next = level(k + 1);
  std::vector<Span> inside;
  for (const Span& s : spansAt(next)) {
    const double mid = (s.left.at.z + s.right.at.z) / 2.0;
    if (mid >= span.left.at.z && mid <= span.right.at.z) {
      inside.push_back(s);
    }
  }
  if (inside.empty()) {
    return; // a pocket's bottom: the next move leaves along the shape
  }
  // Up the shape towards the level before, and the 45 degree escape.
  const ShapePoint top = climb(span.right, aboveLevel).at;
  const double e = roughing_.escape;
  emit(ShapeMotion::Rapid, {top.x + e, top.z - e});
  for (std::size_t j = 0; j < inside.size(); ++j) {
    if (j == 0) {
      emit(ShapeMotion::Rapid, {top.x + e, span.left.at.z});
      enterFirst(span, h, inside[j], next);
    } else {
      follow(last_, inside[j].left);
    }
    cutBelow(inside[j], next, h);
  }
}

/// Down to the left of the first span below `outer`: beside the shape's
/// start as type I goes, else along the shape at the cutting feed.
void PocketRoughing::enterFirst(const Span& outer, double outerLevel,
                                const Span& span, double h) {
  if (span.left.piece < 0) {
    emit(approach_, {h, a_.z});
    return;
  }
  if (outer.left.piece < 0) {
    emit(ShapeMotion::Line, {outerLevel, a_.z});
    emit(ShapeMotion::Line, start_);
    follow({0, start_}, span.left);
    return;
  }
  emit(ShapeMotion::Line, outer.left.at);
  follow(outer.left, span.left);
}

ShapeFault PocketRoughing::run() {
  if (pieces_.empty()) {
    return ShapeFault::None;
  }
  if (!alongT()) {
    return ShapeFault::NotMonotonic;
  }
  double lowest = start_.x;
  for (const Piece& piece : pieces_) {
    lowest = std::min(lowest, piece.move.end.x);
    if (isArc(piece.move)) { // an arc's lowest point may lie inside it
      const ShapePoint c = piece.move.center;
      const double r = std::hypot(piece.from.x - c.x, piece.from.z - c.z);
      if (onArc(-kPi / 2.0, angleOf(piece.from, c),
                sweepOf(piece.move, piece.from))) {
        lowest = std::min(lowest, c.x - r);
      }
    }
  }
  while (level(levels_ + 1) > lowest) {
    ++levels_;
  }
  bool cut = false;
  const double e = roughing_.escape;
  for (const Span& outer : spansAt(a_.x)) {
    std::vector<Span> first;
    for (const Span& s :
         levels_ > 0 ? spansAt(level(1)) : std::vector<Span>{}) {
      const double mid = (s.left.at.z + s.right.at.z) / 2.0;
      if (mid >= outer.left.at.z && mid <= outer.right.at.z) {
        first.push_back(s);
      }
    }
    for (const Span& span : first) {
      if (!cut) {
        enterFirst(outer, a_.x, span, level(1));
      } else {
        follow(last_, span.left);
      }
      cut = true;
      cutBelow(span, level(1), a_.x);
    }
  }
  if (cut) {
    // Out of the last pocket along the shape, then back to A above it.
    follow(last_, end());
    backToA(e);
  }
  // Along the shape with the allowance left on it, then back to A.
  emit(approach_, start_);
  follow({0, start_}, end());
  backToA(e);
  return ShapeFault::None;
}

/// From the shape's end back to A at rapid: first away from the shape to
/// A's level (or e above the end, if higher), then along it, since a
/// straight line to A could cross a rise of the shape before its end.
void PocketRoughing::backToA(double e) {
  const ShapePoint out = end().at;
  const double clear = std::max(a_.x, out.x + e);
  emit(ShapeMotion::Rapid, {clear, out.z});
  emit(ShapeMotion::Rapid, {clear, a_.z});
  if (clear != a_.x) {
    emit(ShapeMotion::Rapid, a_);
  }
}

} // namespace

ShapeFault roughPockets(const Shape& shape, const Roughing& roughing,
                        std::vector<ShapeMove>& out) {
  if (shape.moves.size() < 2) {
    return ShapeFault::None;
  }
  return PocketRoughing(shape, roughing, out).run();
}

} // namespace mbc::rt
