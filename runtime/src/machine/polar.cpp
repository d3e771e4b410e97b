// The polar coordinate command (see polar.h). The end point is worked out
// in input units and rounded to counts once, as the control rounds a
// programmed point to its least increment.
#include "polar.h"

#include <cmath>
#include <numbers>

namespace mbc::rt {

namespace {

struct PlaneIndices {
  int first;  // the radius
  int second; // the angle
};

PlaneIndices planeIndices(const mbrt_ctx& ctx) {
  const PlaneAxes plane = planeAxes(ctx.modal.plane);
  return {ctx.axisOf(plane.letters[0]), ctx.axisOf(plane.letters[1])};
}

bool writes(const MotionWords& words, int axis) {
  return axis >= 0 && (words.axisMask >> axis & 1) != 0;
}

} // namespace

bool writesPlaneWords(const mbrt_ctx& ctx, const MotionWords& words) {
  const PlaneIndices p = planeIndices(ctx);
  return writes(words, p.first) || writes(words, p.second);
}

void polarToCartesian(const mbrt_ctx& ctx, MotionWords& words) {
  const PlaneIndices p = planeIndices(ctx);
  const bool hasRadius = writes(words, p.first);
  const bool hasAngle = writes(words, p.second);
  if (p.first < 0 || p.second < 0 || (!hasRadius && !hasAngle)) {
    return;
  }
  const double scaleX = ctx.axisScale(p.first);
  const double scaleY = ctx.axisScale(p.second);
  const AxisCounts& position = programPosition(ctx);
  const double x = static_cast<double>(position[p.first]) / scaleX;
  const double y = static_cast<double>(position[p.second]) / scaleY;
  constexpr double kDegree = std::numbers::pi / 180.0;
  const bool incremental = ctx.modal.incremental;
  double poleX = 0.0;
  double poleY = 0.0;
  double radius = std::hypot(x, y);
  if (hasRadius) {
    radius = static_cast<double>(words.axis[p.first]) / scaleX;
    if (incremental) {
      poleX = x;
      poleY = y;
    }
  }
  const double current = x == 0.0 && y == 0.0 ? 0.0 : std::atan2(y, x);
  double angle = current;
  if (hasAngle) {
    const double written =
        static_cast<double>(words.axis[p.second]) / scaleY * kDegree;
    angle = incremental ? current + written : written;
  }
  const auto endX = static_cast<Counts>(
      roundToCounts(poleX + radius * std::cos(angle), scaleX));
  const auto endY = static_cast<Counts>(
      roundToCounts(poleY + radius * std::sin(angle), scaleY));
  words.axis[p.first] = incremental ? endX - position[p.first] : endX;
  words.axis[p.second] = incremental ? endY - position[p.second] : endY;
  words.axisMask |= (1U << p.first) | (1U << p.second);
}

} // namespace mbc::rt
