// Vectors, lines and circles of one plane, in counts: what cutter
// compensation needs to place the tool at a corner (cutter_comp.h).
#pragma once

#include <vector>

namespace mbc::rt {

/// A point of a plane: its first and second axis, in counts.
struct PlanePoint {
  double x;
  double y;
};

inline PlanePoint operator+(PlanePoint a, PlanePoint b) {
  return {a.x + b.x, a.y + b.y};
}

inline PlanePoint operator-(PlanePoint a, PlanePoint b) {
  return {a.x - b.x, a.y - b.y};
}

inline PlanePoint operator*(double k, PlanePoint a) {
  return {k * a.x, k * a.y};
}

inline double dot(PlanePoint a, PlanePoint b) {
  return a.x * b.x + a.y * b.y;
}

/// Positive when b turns counter-clockwise from a.
inline double cross(PlanePoint a, PlanePoint b) {
  return a.x * b.y - a.y * b.x;
}

double length(PlanePoint a);
/// `a` of length 1; the zero vector stays zero.
PlanePoint unit(PlanePoint a);

/// `a` turned 90 degrees counter-clockwise: the left of a direction.
inline PlanePoint leftOf(PlanePoint a) {
  return {-a.y, a.x};
}

/// A line (through `point`, along the unit `direction`) or a circle
/// (`center`, `radius`).
struct PlaneCurve {
  bool circle = false;
  PlanePoint point{};
  PlanePoint direction{};
  PlanePoint center{};
  double radius = 0.0;
};

/// Where two curves meet: none, one or two points (a line with itself or
/// parallel lines meet nowhere).
std::vector<PlanePoint> intersections(const PlaneCurve& a, const PlaneCurve& b);

/// The sweep from `from` to `to` about `center` in (0, 2 pi], turning
/// clockwise or not; `from` == `to` is a full circle.
double sweepBetween(PlanePoint from, PlanePoint to, PlanePoint center,
                    bool clockwise);

/// std::fmod(angle, 2 pi) for 0 <= angle < 8 pi, to the same bits: each
/// subtraction is exact (Sterbenz), as fmod's remainder is. fmod was a
/// tenth of an arc block's cost.
double withinTurn(double angle);

} // namespace mbc::rt
