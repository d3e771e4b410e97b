// The polar coordinate command (see polar.h). The end point is worked out
// in input units and rounded to counts once, as the control rounds a
// programmed point to its least increment.
#include "polar.h"

#include <cmath>
#include <numbers>

#include "tool_moves.h"

namespace mbc::rt {

namespace {

bool writes(const MotionWords& words, int axis) {
  return axis >= 0 && (words.axisMask >> axis & 1) != 0;
}

} // namespace

bool writesPlaneWords(const mbrt_ctx& ctx, const MotionWords& words) {
  const PlaneIndex p = planeIndex(ctx); // p: the radius, q: the angle
  return writes(words, p.p) || writes(words, p.q);
}

void polarToCartesian(const mbrt_ctx& ctx, MotionWords& words) {
  const PlaneIndex p = planeIndex(ctx); // p: the radius, q: the angle
  const bool hasRadius = writes(words, p.p);
  const bool hasAngle = writes(words, p.q);
  if (p.p < 0 || p.q < 0 || (!hasRadius && !hasAngle)) {
    return;
  }
  const double scaleX = ctx.axisScale(p.p);
  const double scaleY = ctx.axisScale(p.q);
  const AxisCounts& position = programPosition(ctx);
  const double x = static_cast<double>(position[p.p]) / scaleX;
  const double y = static_cast<double>(position[p.q]) / scaleY;
  constexpr double kDegree = std::numbers::pi / 180.0;
  const bool incremental = ctx.machine.modal.incremental;
  double poleX = 0.0;
  double poleY = 0.0;
  double radius = std::hypot(x, y);
  if (hasRadius) {
    radius = static_cast<double>(words.axis[p.p]) / scaleX;
    if (incremental) {
      poleX = x;
      poleY = y;
    }
  }
  const double current = x == 0.0 && y == 0.0 ? 0.0 : std::atan2(y, x);
  double angle = current;
  if (hasAngle) {
    const double written =
        static_cast<double>(words.axis[p.q]) / scaleY * kDegree;
    angle = incremental ? current + written : written;
  }
  const auto endX = static_cast<Counts>(
      roundToCounts(poleX + radius * std::cos(angle), scaleX));
  const auto endY = static_cast<Counts>(
      roundToCounts(poleY + radius * std::sin(angle), scaleY));
  words.axis[p.p] = incremental ? endX - position[p.p] : endX;
  words.axis[p.q] = incremental ? endY - position[p.q] : endY;
  words.axisMask |= (1U << p.p) | (1U << p.q);
}

} // namespace mbc::rt
