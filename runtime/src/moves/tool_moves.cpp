// The tool moves (tool_moves.h): where the control point goes, how long it
// takes (the simulated #3001/#3002 clock and the summary's cycle time), the
// toolpath's box, and the motion sink. Geometry works on counts of the
// least increment.
#include "tool_moves.h"

#include <mbc/arith.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "frames.h"
#include "lathe_codes.h"
#include "machine_unit.h"
#include "spindle.h"
#include "stroke_check.h"

namespace mbc::rt {

MoveOrigin blockOrigin(const mbrt_ctx& ctx, int cycle) {
  MoveOrigin origin{ctx.run.block.file,
                    ctx.run.block.line,
                    ctx.programName(),
                    ctx.machine.modal.feed,
                    ctx.machine.modal.feedMode,
                    ctx.machine.lastWords[lastWordSlot(LastWord::S)],
                    cycle != 0 ? cycle : ctx.run.cycleLabel};
  origin.surfaceSpeed = ctx.machine.modal.surfaceSpeed;
  origin.spindleLimit = ctx.machine.spindleLimit;
  origin.threading = cutsThread(ctx.machine.modal.motion);
  if (ctx.machine.modal.motion == kVariableLeadMotion) {
    origin.leadChange = ctx.machine.leadChange;
  }
  return origin;
}

namespace {

using Point = PlanePoint;

/// The simulated clocks #3001/#3002 and the cycle time of the summary.
void passTime(mbrt_ctx& ctx, double seconds) {
  ctx.machine.clockMs += seconds * 1000.0;
  ctx.machine.clockHours += seconds / 3600.0;
  ctx.machine.stats.seconds += seconds;
}

/// How far a move goes: over every axis in input units, a degree counting
/// as one unit (as FANUC's feed of a move with a rotary axis does), and
/// along the linear axes alone in mm, for the summary and the rapids.
struct Travel {
  double units = 0.0;
  double mm = 0.0;
  double lead = 0.0; // the longest linear axis travel, input units
};

/// Feed moves take length / F minutes (G94), 1 / F (G93) or length / (F S)
/// (G95); rapids the linear length / rapid rate, the rate being in mm/min
/// whatever the input unit (degrees at the same number when only rotary
/// axes move). `timed`: the length F applies to, in input units, which for
/// a helix is the arc in its plane (FANUC: F is the feed along the arc).
/// A thread (G32) goes its lead F per revolution along its longer axis;
/// G34's lead grows by K each revolution: L n + K n^2 / 2 = length gives
/// the revolutions n. `turnMinutes`: one revolution's mean time in G96
/// (spindle.h), else 0.
void advanceClock(mbrt_ctx& ctx, const Travel& travel, bool rapid, double timed,
                  const MoveOrigin& origin, double turnMinutes = 0.0) {
  double minutes = 0.0;
  if (origin.threading && !rapid) {
    timed = travel.lead;
    if (origin.leadChange != 0.0) { // in leads of F: the same clock below
      const double k = origin.leadChange;
      const double l = origin.feed;
      timed = l * (std::sqrt(l * l + 2.0 * k * timed) - l) / k;
    }
  }
  if (rapid) {
    minutes =
        (travel.mm > 0.0 ? travel.mm : travel.units) / ctx.profile.rapidRate;
  } else if (origin.feedMode == 93) {
    minutes = 1.0 / origin.feed;
  } else if (turnMinutes > 0.0) {
    minutes = timed / origin.feed * turnMinutes;
  } else if (origin.feedMode == 95 || origin.threading) {
    minutes = timed / (origin.feed * origin.spindle);
  } else {
    minutes = timed / origin.feed;
  }
  passTime(ctx, minutes * 60.0);
  (rapid ? ctx.machine.stats.rapidLength : ctx.machine.stats.feedLength) +=
      travel.mm;
}

/// Widens the toolpath's bounding box by a coordinate of a workpiece point
/// (counts) that follows the first.
void widenBox(mbrt_ctx& ctx, int axis, double counts) {
  CountsBox& box = ctx.machine.stats.box[ctx.machine.modal.inch];
  box.low[axis] = std::min(box.low[axis], counts);
  box.high[axis] = std::max(box.high[axis], counts);
}

void widenBox(mbrt_ctx& ctx, const AxisCounts& work) {
  CountsBox& box = ctx.machine.stats.box[ctx.machine.modal.inch];
  const bool first = !box.any;
  box.any = true;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    const auto counts = static_cast<double>(ctx.shown(axis, work[axis]));
    box.low[axis] = first ? counts : std::min(box.low[axis], counts);
    box.high[axis] = first ? counts : std::max(box.high[axis], counts);
  }
}

/// The control point moves to `machine`, workpiece position `work`; the
/// motion goes to the sink with its arc centre in workpiece counts.
void moveTo(mbrt_ctx& ctx, int kind, const AxisCounts& work,
            const AxisCounts& machine, Point center, const MoveOrigin& origin) {
  widenBox(ctx, work);
  ++ctx.machine.moves;
  if (ctx.host.motionSink.fn == nullptr) {
    ctx.machine.position = machine;
    return;
  }
  const AxisCounts start = machineToWork(ctx, ctx.machine.position);
  ctx.machine.position = machine;
  const double scale = ctx.scale();
  const PlaneAxes plane = planeAxes(ctx.machine.modal.plane);
  mbrt_motion motion{};
  motion.kind = kind;
  motion.axis_count = ctx.axisCount();
  motion.axis_names = ctx.profile.axes.c_str();
  motion.diameter_mask = ctx.profile.diameterMask;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    const double axisScale = ctx.axisScale(axis);
    motion.end[axis] = countsToUnits(ctx.shown(axis, work[axis]), axisScale);
    motion.machine[axis] =
        countsToUnits(ctx.shown(axis, machine[axis]), axisScale);
    motion.start[axis] = countsToUnits(ctx.shown(axis, start[axis]), axisScale);
    // Without compensation the programmed point is the end: a division
    // less per axis on every move.
    motion.programmed[axis] =
        origin.programmed != nullptr
            ? countsToUnits(ctx.shown(axis, (*origin.programmed)[axis]),
                            axisScale)
            : motion.end[axis];
  }
  motion.feed = kind == MBRT_MOTION_RAPID ? 0.0 : origin.feed;
  motion.plane = ctx.machine.modal.plane;
  motion.center_axes[0] = plane.letters[0];
  motion.center_axes[1] = plane.letters[1];
  for (int i = 0; i < 2; ++i) {
    const int axis = ctx.axisOf(plane.letters[i]);
    motion.center[i] = (i == 0 ? center.x : center.y) /
                       (axis >= 0 ? ctx.axisScale(axis) : scale);
  }
  motion.decimals = ctx.decimals();
  motion.file = origin.file;
  motion.line = origin.line;
  motion.program = origin.program;
  motion.cycle = origin.cycle;
  callSink(ctx,
           [&] { ctx.host.motionSink.fn(ctx.host.motionSink.user, &motion); });
}

/// The length of a move of the control point: the path in the workpiece
/// frame (`path`, counts of linear axes) combined with what the other axes
/// travel.
Travel travel(const mbrt_ctx& ctx, const AxisCounts& machine,
              std::uint32_t pathAxes, double path) {
  double linear = 0.0;
  double rotary = 0.0;
  double lead = 0.0;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((pathAxes >> axis & 1) == 0) {
      const auto delta =
          static_cast<double>(machine[axis] - ctx.machine.position[axis]);
      (ctx.isRotary(axis) ? rotary : linear) += delta * delta;
      lead = ctx.isRotary(axis) ? lead : std::max(lead, std::fabs(delta));
    }
  }
  // hypot(0, d) is d exactly; std::hypot is slow enough to show per move.
  const double counts =
      path == 0.0 ? std::sqrt(linear) : std::hypot(path, std::sqrt(linear));
  const double units = counts / ctx.scale();
  const double degrees = std::sqrt(rotary) / kCountsPerDegree;
  return {degrees == 0.0 ? units : std::hypot(units, degrees),
          counts / ctx.countsPerMm(), lead / ctx.scale()};
}

/// The points of an arc farthest along its plane axes, where it passes
/// 0, 90, 180 or 270 degrees.
void widenBoxByArc(mbrt_ctx& ctx, int p, int q, Point center, Point start,
                   double radius, double sweep, bool clockwise) {
  // The cosines and sines of the quarters as the C library gives them (cos
  // pi/2 is not 0), computed once: they cost more than the rest per arc.
  struct Quarter {
    double angle, cos, sin;
  };

  static const std::array<Quarter, 4> kQuarters = [] {
    std::array<Quarter, 4> quarters{};
    for (int i = 0; i < 4; ++i) {
      const double angle = i * std::numbers::pi / 2.0;
      quarters[i] = {angle, std::cos(angle), std::sin(angle)};
    }
    return quarters;
  }();
  const double begin = std::atan2(start.y - center.y, start.x - center.x);
  for (const Quarter& quarter : kQuarters) {
    double travel = clockwise ? begin - quarter.angle : quarter.angle - begin;
    travel = withinTurn(travel + 4.0 * std::numbers::pi);
    if (travel <= sweep) {
      widenBox(ctx, p, center.x + radius * quarter.cos);
      widenBox(ctx, q, center.y + radius * quarter.sin);
    }
  }
}

} // namespace

mbrt_status moveStraightTo(mbrt_ctx& ctx, const AxisCounts& work,
                           const AxisCounts& machine, bool rapid,
                           const MoveOrigin& origin) {
  if (checksStroke(ctx)) {
    if (const mbrt_status status = checkLineStroke(ctx, machine, origin)) {
      return status;
    }
  }
  const Travel length = travel(ctx, machine, 0, 0.0);
  advanceClock(ctx, length, rapid, length.units, origin,
               rapid ? 0.0 : lineTurnMinutes(ctx, origin, work));
  moveTo(ctx, rapid ? MBRT_MOTION_RAPID : MBRT_MOTION_LINEAR, work, machine,
         {0, 0}, origin);
  return 0;
}

mbrt_status moveWorkStraight(mbrt_ctx& ctx, const AxisCounts& work, bool rapid,
                             const MoveOrigin& origin) {
  return moveStraightTo(ctx, work, workToMachine(ctx, work), rapid, origin);
}

namespace {

/// moveArcTo from `workStart`, the control point's workpiece position,
/// which the caller has already found.
mbrt_status arcFromStart(mbrt_ctx& ctx, const AxisCounts& workStart,
                         const AxisCounts& work, PlanePoint center,
                         double radius, double sweep, bool clockwise,
                         const MoveOrigin& origin) {
  const auto [p, q] = planeIndex(ctx);
  const Point from{static_cast<double>(workStart[p]),
                   static_cast<double>(workStart[q])};
  const AxisCounts machine = workToMachine(ctx, work);
  const ArcPath arc{p, q, center, from, sweep, clockwise};
  if (checksStroke(ctx)) {
    if (const mbrt_status status =
            checkArcStroke(ctx, work, machine, arc, origin)) {
      return status;
    }
  }
  advanceClock(ctx,
               travel(ctx, machine,
                      (std::uint32_t{1} << p) | (std::uint32_t{1} << q),
                      radius * sweep),
               false, radius * sweep / ctx.scale(), origin,
               arcTurnMinutes(ctx, origin, arc, workStart));
  moveTo(ctx, clockwise ? MBRT_MOTION_CW : MBRT_MOTION_CCW, work, machine,
         center, origin);
  widenBoxByArc(ctx, p, q, center, from, radius, sweep, clockwise);
  return 0;
}

} // namespace

mbrt_status moveArcTo(mbrt_ctx& ctx, const AxisCounts& work, PlanePoint center,
                      double radius, double sweep, bool clockwise,
                      const MoveOrigin& origin) {
  return arcFromStart(ctx, machineToWork(ctx, ctx.machine.position), work,
                      center, radius, sweep, clockwise, origin);
}

mbrt_status moveWorkArc(mbrt_ctx& ctx, const AxisCounts& work,
                        PlanePoint center, bool clockwise,
                        const MoveOrigin& origin) {
  const auto [p, q] = planeIndex(ctx);
  const AxisCounts workStart = machineToWork(ctx, ctx.machine.position);
  const Point from{static_cast<double>(workStart[p]),
                   static_cast<double>(workStart[q])};
  const Point to{static_cast<double>(work[p]), static_cast<double>(work[q])};
  return arcFromStart(ctx, workStart, work, center,
                      std::hypot(from.x - center.x, from.y - center.y),
                      sweepBetween(from, to, center, clockwise), clockwise,
                      origin);
}

void switchUnits(mbrt_ctx& ctx, bool inch) {
  if (ctx.machine.modal.inch == inch) {
    return;
  }
  const double factor = unitCountsFactor(inch);
  const auto convert = [factor](Counts& counts) {
    counts = static_cast<Counts>(
        roundHalfAway(static_cast<double>(counts) * factor));
  };
  // Rotary axes stay in degrees.
  const auto convertAll = [&](AxisCounts& counts) {
    for (int axis = 0; axis < MBRT_MAX_AXES; ++axis) {
      if (!ctx.isRotary(axis)) {
        convert(counts[axis]);
      }
    }
  };
  const auto scaleAll = [&](AxisValues& values) {
    for (int axis = 0; axis < MBRT_MAX_AXES; ++axis) {
      if (!ctx.isRotary(axis)) {
        values[axis] *= factor;
      }
    }
  };
  convertAll(
      ctx.machine.position); // the offset memory keeps the machine's unit
  Frames& frames = ctx.machine.frames;
  convertAll(ctx.machine.skipPosition);
  convertAll(ctx.machine.intermediate);
  convertAll(frames.local);
  convertAll(frames.preset);
  convertAll(frames.toolGeometry); // a lathe's tool offsets in force
  convertAll(frames.toolWear);
  convert(frames.length);
  scaleAll(frames.mirrorCenter);
  scaleAll(frames.scaleCenter);
  frames.rotationCenter[0] *= factor;
  frames.rotationCenter[1] *= factor;
  ctx.machine.modal.inch = inch;
  resyncProgram(ctx);
}

const AxisCounts& programPosition(const mbrt_ctx& ctx) {
  return ctx.machine.program;
}

void dwell(mbrt_ctx& ctx, double seconds) {
  passTime(ctx, seconds);
}

} // namespace mbc::rt
