// Spindle speed along a lathe's moves (spindle.h). In G96 one revolution
// takes 2 pi r / (k S) minutes at radius r (k = 1000 mm per m, or 12 inches
// per foot), at least 1 / limit: piecewise linear in r, so a straight move
// averages exactly by its pieces; an arc by Simpson's rule.
#include "spindle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "frames.h"

namespace mbc::rt {

namespace {

constexpr int kArcIntervals = 64; // even, for Simpson's rule

/// Minutes per revolution at a distance `radius` (input units) from the
/// spindle axis.
struct TurnTime {
  double perRadius = 0.0; // minutes per revolution per unit of radius
  double least = 0.0;     // 1 / the speed limit, 0 without one

  double at(double radius) const {
    return std::max(std::fabs(radius) * perRadius, least);
  }
};

TurnTime turnTime(const mbrt_ctx& ctx, const MoveOrigin& origin) {
  const double unitsPerSurfaceUnit = ctx.machine.modal.inch ? 12.0 : 1000.0;
  double limit = origin.spindleLimit;
  if (const double top = ctx.profile.parameter(3772); top > 0.0) {
    limit = limit > 0.0 ? std::min(limit, top) : top;
  }
  return {2.0 * std::numbers::pi / (unitsPerSurfaceUnit * origin.spindle),
          limit > 0.0 ? 1.0 / limit : 0.0};
}

/// The programmed point's distance from the spindle axis, input units.
double radiusOf(const mbrt_ctx& ctx, Counts x) {
  return static_cast<double>(x) / ctx.scale();
}

/// The axis whose position sets the speed in G96 (X), -1 outside G96.
int surfaceSpeedAxis(const mbrt_ctx& ctx, const MoveOrigin& origin) {
  return origin.surfaceSpeed ? ctx.axisOf('X') : -1;
}

} // namespace

double lineTurnMinutes(const mbrt_ctx& ctx, const MoveOrigin& origin,
                       const AxisCounts& to) {
  const int x = surfaceSpeedAxis(ctx, origin);
  if (x < 0) {
    return 0.0;
  }
  const AxisCounts from = machineToWork(ctx, ctx.machine.position);
  const TurnTime time = turnTime(ctx, origin);
  const double r0 = radiusOf(ctx, from[x]);
  const double r1 = radiusOf(ctx, to[x]);
  if (r0 == r1) {
    return time.at(r0);
  }
  // Where the time per revolution bends: the axis and the capped radius.
  // Unused places stay past the end (2) and sort last.
  std::array<double, 5> cuts{0.0, 1.0, 2.0, 2.0, 2.0};
  int count = 2;
  const double capped = time.perRadius > 0.0 ? time.least / time.perRadius : 0;
  for (const double r : {0.0, capped, -capped}) {
    const double t = (r - r0) / (r1 - r0);
    if (t > 0.0 && t < 1.0) {
      cuts[count++] = t;
    }
  }
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  for (int i = 1; i < count; ++i) {
    const double a = r0 + cuts[i - 1] * (r1 - r0);
    const double b = r0 + cuts[i] * (r1 - r0);
    sum += (cuts[i] - cuts[i - 1]) * (time.at(a) + time.at(b)) / 2.0;
  }
  return sum;
}

double arcTurnMinutes(const mbrt_ctx& ctx, const MoveOrigin& origin,
                      const ArcPath& arc, const AxisCounts& start) {
  const int x = surfaceSpeedAxis(ctx, origin);
  if (x < 0) {
    return 0.0;
  }
  const TurnTime time = turnTime(ctx, origin);
  if (x != arc.p && x != arc.q) {
    return time.at(radiusOf(ctx, start[x]));
  }
  const PlanePoint offset = arc.from - arc.center;
  const double radius = length(offset);
  const double begin = std::atan2(offset.y, offset.x);
  const double turn = arc.clockwise ? -arc.sweep : arc.sweep;
  double sum = 0.0;
  for (int i = 0; i <= kArcIntervals; ++i) {
    const double angle = begin + turn * i / kArcIntervals;
    const double counts = x == arc.p ? arc.center.x + radius * std::cos(angle)
                                     : arc.center.y + radius * std::sin(angle);
    const double weight = i == 0 || i == kArcIntervals ? 1.0
                          : i % 2 != 0                 ? 4.0
                                                       : 2.0;
    sum += weight * time.at(counts / ctx.scale());
  }
  return sum / (3.0 * kArcIntervals);
}

} // namespace mbc::rt
