// Intersections of lines and circles, solved in closed form.
#include "plane_geometry.h"

#include <cmath>
#include <numbers>

namespace mbc::rt {

double length(PlanePoint a) {
  return std::hypot(a.x, a.y);
}

PlanePoint unit(PlanePoint a) {
  const double n = length(a);
  return n > 0.0 ? (1.0 / n) * a : a;
}

namespace {

/// Directions closer than this (as the sine of their angle) are parallel.
constexpr double kParallel = 1e-12;
/// Curves that miss each other by less than half a count touch: tangent
/// joins, exact in the program, miss by rounding in double.
constexpr double kTouch = 0.5;

std::vector<PlanePoint> lineLine(const PlaneCurve& a, const PlaneCurve& b) {
  const double det = cross(a.direction, b.direction);
  if (std::fabs(det) <= kParallel) {
    return {};
  }
  const double t = cross(b.point - a.point, b.direction) / det;
  return {a.point + t * a.direction};
}

std::vector<PlanePoint> lineCircle(const PlaneCurve& line,
                                   const PlaneCurve& circle) {
  // The foot of the perpendicular from the centre, then half the chord.
  const PlanePoint toCenter = circle.center - line.point;
  const PlanePoint foot =
      line.point + dot(toCenter, line.direction) * line.direction;
  const double distance = length(circle.center - foot);
  if (distance > circle.radius + kTouch) {
    return {};
  }
  const double half = std::sqrt(
      std::max(0.0, circle.radius * circle.radius - distance * distance));
  if (half == 0.0) {
    return {foot};
  }
  return {foot - half * line.direction, foot + half * line.direction};
}

std::vector<PlanePoint> circleCircle(const PlaneCurve& a, const PlaneCurve& b) {
  const PlanePoint between = b.center - a.center;
  const double d = length(between);
  if (d == 0.0 || d > a.radius + b.radius + kTouch ||
      d < std::fabs(a.radius - b.radius) - kTouch) {
    return {};
  }
  const double along =
      (d * d + a.radius * a.radius - b.radius * b.radius) / (2.0 * d);
  const double height =
      std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
  const PlanePoint axis = (1.0 / d) * between;
  const PlanePoint base = a.center + along * axis;
  if (height == 0.0) {
    return {base};
  }
  return {base + height * leftOf(axis), base - height * leftOf(axis)};
}

} // namespace

std::vector<PlanePoint> intersections(const PlaneCurve& a,
                                      const PlaneCurve& b) {
  if (!a.circle && !b.circle) {
    return lineLine(a, b);
  }
  if (a.circle && b.circle) {
    return circleCircle(a, b);
  }
  return a.circle ? lineCircle(b, a) : lineCircle(a, b);
}

double sweepBetween(PlanePoint from, PlanePoint to, PlanePoint center,
                    bool clockwise) {
  if (from.x == to.x && from.y == to.y) {
    return 2.0 * std::numbers::pi;
  }
  const double a0 = std::atan2(from.y - center.y, from.x - center.x);
  const double a1 = std::atan2(to.y - center.y, to.x - center.x);
  double sweep = clockwise ? a0 - a1 : a1 - a0;
  if (sweep <= 0.0) {
    sweep += 2.0 * std::numbers::pi;
  }
  return sweep;
}

double withinTurn(double angle) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  if (angle >= 2.0 * kTurn) {
    angle -= 2.0 * kTurn;
  }
  if (angle >= kTurn) {
    angle -= kTurn;
  }
  return angle;
}

} // namespace mbc::rt
