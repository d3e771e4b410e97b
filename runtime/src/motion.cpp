// Linear and circular motion (G00..G03): end points, arc centres from I J K
// or R, helical arcs, the simulated #3001/#3002 clock and the motion sink.
// Geometry works on counts of the least increment; only arc centres from R
// are not whole counts.
#include "motion.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

namespace mbc::rt {

namespace {

constexpr double kMmPerInch = 25.4;

struct Point {
  double x;
  double y;
};

/// The two axes of an arc plane and the I/J/K index of each.
struct PlaneAxes {
  char letters[2];
  int centerIndex[2];
};

PlaneAxes planeAxes(int plane) {
  switch (plane) {
    case 18:
      return {{'Z', 'X'}, {2, 0}};
    case 19:
      return {{'Y', 'Z'}, {1, 2}};
    default:
      return {{'X', 'Y'}, {0, 1}};
  }
}

const AxisCounts& activeOffset(const mbrt_ctx& ctx) {
  return ctx.workOffsets[ctx.modal.workOffset];
}

AxisCounts workTarget(const mbrt_ctx& ctx, const MotionWords& words,
                      const AxisCounts& start) {
  AxisCounts target = start;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((words.axisMask >> axis & 1) != 0) {
      target[axis] = ctx.modal.incremental ? start[axis] + words.axis[axis]
                                           : words.axis[axis];
    }
  }
  return target;
}

/// Feed moves take length / F minutes (G94); rapids length / rapid rate,
/// the rate being in mm/min whatever the input unit.
void advanceClock(mbrt_ctx& ctx, double lengthCounts, bool rapid) {
  const double length = lengthCounts / ctx.scale();
  double minutes = 0.0;
  if (rapid) {
    minutes =
        length * (ctx.modal.inch ? kMmPerInch : 1.0) / ctx.profile.rapidRate;
  } else {
    minutes = length / ctx.modal.feed;
  }
  ctx.clockMs += minutes * 60'000.0;
  ctx.clockHours += minutes / 60.0;
}

void moveTo(mbrt_ctx& ctx, const AxisCounts& target) {
  const AxisCounts& offset = activeOffset(ctx);
  const AxisCounts& external = ctx.workOffsets[kExternalOffset];
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    ctx.machine[axis] = target[axis] + offset[axis] + external[axis];
  }
  ++ctx.moves;
}

void emit(mbrt_ctx& ctx, int kind, const AxisCounts& target, Point center,
          int cycle = 0) {
  if (ctx.motionSink.fn == nullptr) {
    return;
  }
  const double scale = ctx.scale();
  const PlaneAxes plane = planeAxes(ctx.modal.plane);
  mbrt_motion motion{};
  motion.kind = kind;
  motion.axis_count = ctx.axisCount();
  motion.axis_names = ctx.profile.axes.c_str();
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    motion.end[axis] = countsToUnits(target[axis], scale);
  }
  motion.feed = kind == MBRT_MOTION_RAPID ? 0.0 : ctx.modal.feed;
  motion.plane = ctx.modal.plane;
  motion.center_axes[0] = plane.letters[0];
  motion.center_axes[1] = plane.letters[1];
  motion.center[0] = center.x / scale;
  motion.center[1] = center.y / scale;
  motion.decimals = ctx.decimals();
  motion.file = ctx.block.file;
  motion.line = ctx.block.line;
  motion.program = ctx.programName();
  motion.cycle = cycle;
  ctx.motionSink.fn(ctx.motionSink.user, &motion);
}

double distance(const AxisCounts& from, const AxisCounts& to, int axisCount,
                std::uint32_t skipMask) {
  double sum = 0.0;
  for (int axis = 0; axis < axisCount; ++axis) {
    if ((skipMask >> axis & 1) == 0) {
      const auto delta = static_cast<double>(to[axis] - from[axis]);
      sum += delta * delta;
    }
  }
  return std::sqrt(sum);
}

/// R > 0 takes the arc of at most 180 degrees, R < 0 the longer one; an R
/// shorter than half the chord is stretched to it, as FANUC does.
Point centerFromRadius(Point start, Point end, double r, bool clockwise) {
  const double dx = end.x - start.x;
  const double dy = end.y - start.y;
  const double chord = std::hypot(dx, dy);
  const double half = chord / 2.0;
  const double radius = std::max(std::fabs(r), half);
  const double height = std::sqrt(radius * radius - half * half);
  // The centre of a short counter-clockwise arc lies left of the chord.
  double side = clockwise ? -1.0 : 1.0;
  if (r < 0) {
    side = -side;
  }
  return {start.x + dx / 2.0 - side * height * dy / chord,
          start.y + dy / 2.0 + side * height * dx / chord};
}

/// Sweep angle of the arc in (0, 2 pi]; start == end is a full circle.
double sweepAngle(Point start, Point end, Point center, bool clockwise) {
  if (start.x == end.x && start.y == end.y) {
    return 2.0 * std::numbers::pi;
  }
  const double a0 = std::atan2(start.y - center.y, start.x - center.x);
  const double a1 = std::atan2(end.y - center.y, end.x - center.x);
  double sweep = clockwise ? a0 - a1 : a1 - a0;
  if (sweep <= 0.0) {
    sweep += 2.0 * std::numbers::pi;
  }
  return sweep;
}

/// PS0020 when the start and end radii differ by more than parameter 3410.
mbrt_status checkRadii(mbrt_ctx& ctx, Point start, Point end, Point center) {
  const double tolerance = ctx.profile.parameter(3410) *
                           (ctx.modal.inch ? 10'000.0 / kMmPerInch : 1000.0);
  const double startRadius = std::hypot(start.x - center.x, start.y - center.y);
  const double endRadius = std::hypot(end.x - center.x, end.y - center.y);
  if (tolerance > 0.0 && std::fabs(startRadius - endRadius) > tolerance) {
    return raise(ctx, AlarmId::ArcRadiusTolerance,
                 fmt::format("radius {:.4f} at the start, {:.4f} at the end",
                             startRadius / ctx.scale(),
                             endRadius / ctx.scale()));
  }
  return 0;
}

mbrt_status moveArc(mbrt_ctx& ctx, const MotionWords& words,
                    const AxisCounts& start, const AxisCounts& target) {
  const PlaneAxes plane = planeAxes(ctx.modal.plane);
  const int p = ctx.axisOf(plane.letters[0]);
  const int q = ctx.axisOf(plane.letters[1]);
  if (p < 0 || q < 0) {
    return raise(ctx, AlarmId::ArcNoRadius,
                 fmt::format("G{} arcs need axes {} and {}", ctx.modal.plane,
                             plane.letters[0], plane.letters[1]));
  }
  const bool clockwise = ctx.modal.motion == 2;
  const Point from{static_cast<double>(start[p]),
                   static_cast<double>(start[q])};
  const Point to{static_cast<double>(target[p]),
                 static_cast<double>(target[q])};
  Point center{};
  if (words.hasR) {
    if (from.x == to.x && from.y == to.y) {
      return 0; // FANUC: R with start == end makes no motion at all
    }
    center =
        centerFromRadius(from, to, static_cast<double>(words.r), clockwise);
  } else if (words.centerMask != 0) {
    center = {from.x + static_cast<double>(words.center[plane.centerIndex[0]]),
              from.y + static_cast<double>(words.center[plane.centerIndex[1]])};
    if (const mbrt_status status = checkRadii(ctx, from, to, center)) {
      return status;
    }
  } else {
    return raise(ctx, AlarmId::ArcNoRadius, "arc without R or I, J, K");
  }
  const double radius = std::hypot(from.x - center.x, from.y - center.y);
  const double arc = radius * sweepAngle(from, to, center, clockwise);
  const double helix =
      distance(start, target, ctx.axisCount(),
               (std::uint32_t{1} << p) | (std::uint32_t{1} << q));
  advanceClock(ctx, std::hypot(arc, helix), false);
  moveTo(ctx, target);
  emit(ctx, clockwise ? MBRT_MOTION_CW : MBRT_MOTION_CCW, target, center);
  return 0;
}

} // namespace

Counts workCounts(const mbrt_ctx& ctx, int axis) {
  return ctx.machine[axis] - activeOffset(ctx)[axis] -
         ctx.workOffsets[kExternalOffset][axis];
}

void switchUnits(mbrt_ctx& ctx, bool inch) {
  if (ctx.modal.inch == inch) {
    return;
  }
  // 0.0001 inch is 2.54 counts of 0.001 mm.
  const auto convert = [inch](Counts& counts) {
    const auto value = static_cast<double>(counts);
    counts =
        static_cast<Counts>(roundHalfAway(inch ? value / 2.54 : value * 2.54));
  };
  for (Counts& counts : ctx.machine) {
    convert(counts);
  }
  for (AxisCounts& offset : ctx.workOffsets) {
    for (Counts& counts : offset) {
      convert(counts);
    }
  }
  ctx.modal.inch = inch;
}

AxisCounts workPosition(const mbrt_ctx& ctx) {
  AxisCounts position{};
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    position[axis] = workCounts(ctx, axis);
  }
  return position;
}

namespace {

/// PS0011 for a feed move without F; `cycle` names the canned cycle.
mbrt_status checkFeed(mbrt_ctx& ctx, int cycle) {
  if (ctx.modal.feed > 0.0) {
    return 0;
  }
  return raise(ctx, AlarmId::FeedZero,
               cycle != 0 ? fmt::format("G{} needs F greater than 0", cycle)
                          : fmt::format("G{:02} needs F greater than 0",
                                        ctx.modal.motion));
}

mbrt_status moveLine(mbrt_ctx& ctx, const AxisCounts& start,
                     const AxisCounts& target, bool rapid, int cycle) {
  if (!rapid) {
    if (const mbrt_status status = checkFeed(ctx, cycle)) {
      return status;
    }
  }
  advanceClock(ctx, distance(start, target, ctx.axisCount(), 0), rapid);
  moveTo(ctx, target);
  emit(ctx, rapid ? MBRT_MOTION_RAPID : MBRT_MOTION_LINEAR, target, {0, 0},
       cycle);
  return 0;
}

} // namespace

mbrt_status moveStraight(mbrt_ctx& ctx, const AxisCounts& target, bool rapid,
                         int cycle) {
  return moveLine(ctx, workPosition(ctx), target, rapid, cycle);
}

namespace {

/// The target whose axes in `mask` sit at `machine` in machine coordinates.
AxisCounts machineTarget(const mbrt_ctx& ctx, std::uint32_t mask,
                         const AxisCounts& machine) {
  AxisCounts target = workPosition(ctx);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((mask >> axis & 1) != 0) {
      target[axis] = machine[axis] - ctx.machine[axis] + workCounts(ctx, axis);
    }
  }
  return target;
}

mbrt_status rapidIfMoving(mbrt_ctx& ctx, const AxisCounts& target) {
  return target == workPosition(ctx) ? 0 : moveStraight(ctx, target, true);
}

} // namespace

mbrt_status returnToReference(mbrt_ctx& ctx, const MotionWords& words) {
  const AxisCounts intermediate = workTarget(ctx, words, workPosition(ctx));
  if (const mbrt_status status = rapidIfMoving(ctx, intermediate)) {
    return status;
  }
  return rapidIfMoving(ctx, machineTarget(ctx, words.axisMask, AxisCounts{}));
}

mbrt_status moveInMachineCoordinates(mbrt_ctx& ctx, const MotionWords& words) {
  if (ctx.modal.incremental) {
    return 0;
  }
  return rapidIfMoving(ctx, machineTarget(ctx, words.axisMask, words.axis));
}

void dwell(mbrt_ctx& ctx, double seconds) {
  ctx.clockMs += seconds * 1000.0;
  ctx.clockHours += seconds / 3600.0;
}

mbrt_status executeMotion(mbrt_ctx& ctx, const MotionWords& words) {
  const int mode = ctx.modal.motion;
  const AxisCounts start = workPosition(ctx);
  const AxisCounts target = workTarget(ctx, words, start);
  if (mode == 0 || mode == 1) {
    return moveLine(ctx, start, target, mode == 0, 0);
  }
  if (const mbrt_status status = checkFeed(ctx, 0)) {
    return status;
  }
  return moveArc(ctx, words, start, target);
}

} // namespace mbc::rt
