// Linear and circular motion (G00..G03): end points, arc centres from I J K
// or R, helical arcs, the simulated #3001/#3002 clock and the motion sink.
// Geometry works on counts of the least increment; only arc centres from R
// are not whole counts.
#include "motion.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numbers>

#include "corner_blends.h"
#include "corner_state.h"
#include "cutter_comp.h"
#include "cutter_comp_state.h"
#include "frames.h"
#include "lathe_codes.h"
#include "lathe_corners.h"
#include "lathe_cycles.h"
#include "lathe_shapes.h"
#include "machine_unit.h"
#include "plane_geometry.h"
#include "spindle.h"

namespace mbc::rt {

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

PlaneIndex planeIndex(const mbrt_ctx& ctx) {
  const PlaneAxes plane = planeAxes(ctx.machine.modal.plane);
  return {ctx.axisOf(plane.letters[0]), ctx.axisOf(plane.letters[1])};
}

namespace {

using Point = PlanePoint;

/// G90 on an axis that rolls over: the command within one rotation,
/// reached the shorter way (a half turn goes positive), or with 1008#1 RAB
/// the way the command's sign says.
Counts rolloverTarget(const mbrt_ctx& ctx, int axis, Counts start,
                      Counts command) {
  const Counts turn = ctx.rotation(axis);
  Counts delta = ctx.shown(axis, command) - ctx.shown(axis, start);
  if ((ctx.profile.bySignMask >> axis & 1) != 0) {
    if (command >= 0 && delta < 0) {
      delta += turn;
    } else if (command < 0 && delta > 0) {
      delta -= turn;
    }
  } else if (delta > turn / 2) {
    delta -= turn;
  } else if (delta <= -turn / 2) {
    delta += turn;
  }
  return start + delta;
}

AxisCounts workTarget(const mbrt_ctx& ctx, const MotionWords& words,
                      const AxisCounts& start) {
  AxisCounts target = start;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((words.axisMask >> axis & 1) == 0) {
      continue;
    }
    if (ctx.machine.modal.incremental ||
        (words.incrementalMask >> axis & 1) != 0) {
      target[axis] = start[axis] + words.axis[axis];
    } else if (ctx.rollsOver(axis)) {
      target[axis] = rolloverTarget(ctx, axis, start[axis], words.axis[axis]);
    } else {
      target[axis] = words.axis[axis];
    }
  }
  return target;
}

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
    const Counts programmed =
        origin.programmed != nullptr ? (*origin.programmed)[axis] : work[axis];
    motion.programmed[axis] =
        countsToUnits(ctx.shown(axis, programmed), axisScale);
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

/// R > 0 takes the arc of at most 180 degrees, R < 0 the longer one; an R
/// short of half the chord by the radius tolerance at most
/// (checkRadiusReaches) is stretched to it.
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

/// PS0020 when the start and end radii differ by more than parameter 3410.
mbrt_status checkRadii(mbrt_ctx& ctx, double startRadius, Point end,
                       Point center) {
  const double tolerance = ctx.profile.parameter(3410) * ctx.countsPerMm();
  const double endRadius = std::hypot(end.x - center.x, end.y - center.y);
  if (tolerance > 0.0 && std::fabs(startRadius - endRadius) > tolerance) {
    return raise(ctx, AlarmId::ArcRadiusTolerance,
                 fmt::format("radius {:.4f} at the start, {:.4f} at the end",
                             startRadius / ctx.scale(),
                             endRadius / ctx.scale()));
  }
  return 0;
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

/// A straight move from the program position to `target` as cutter
/// compensation takes it; the program position is then `target`.
HeldMove straightTo(mbrt_ctx& ctx, const AxisCounts& target, bool rapid) {
  HeldMove move;
  move.rapid = rapid;
  move.start = programToWork(ctx, ctx.machine.program);
  move.end = programToWork(ctx, target);
  ctx.machine.program = target;
  return move;
}

/// G28, G29 and G30 under cutter compensation: the tool leaves the offset
/// on its way to the intermediate point `target` (program coordinates), as
/// a cancel move does; the next move in the plane starts it again.
mbrt_status leaveOffsetAt(mbrt_ctx& ctx, const AxisCounts& target) {
  if (!ctx.compensation->engaged) {
    return 0;
  }
  return cancelCompensation(ctx, straightTo(ctx, target, true));
}

Point planePoint(const AxisValues& point, int p, int q) {
  return {point[p], point[q]};
}

} // namespace

std::optional<PlanePoint> arcCenter(const mbrt_ctx& ctx,
                                    const MotionWords& words,
                                    const AxisCounts& start,
                                    const AxisCounts& target, bool clockwise) {
  const PlaneAxes plane = planeAxes(ctx.machine.modal.plane);
  const auto [p, q] = planeIndex(ctx);
  const Point from{static_cast<double>(start[p]),
                   static_cast<double>(start[q])};
  if (words.hasR) {
    return centerFromRadius(
        from, {static_cast<double>(target[p]), static_cast<double>(target[q])},
        static_cast<double>(words.r), clockwise);
  }
  if (words.centerMask != 0) {
    return Point{
        from.x + static_cast<double>(words.center[plane.centerIndex[0]]),
        from.y + static_cast<double>(words.center[plane.centerIndex[1]])};
  }
  return std::nullopt;
}

mbrt_status checkRadiusReaches(mbrt_ctx& ctx, const MotionWords& words,
                               const AxisCounts& start,
                               const AxisCounts& target) {
  if (!words.hasR) {
    return 0;
  }
  const auto [p, q] = planeIndex(ctx);
  const double tolerance = ctx.profile.parameter(3410) * ctx.countsPerMm();
  const double half = std::hypot(static_cast<double>(target[p] - start[p]),
                                 static_cast<double>(target[q] - start[q])) /
                      2.0;
  const auto radius = static_cast<double>(std::abs(words.r));
  if (tolerance > 0.0 && half - radius > tolerance) {
    return raise(ctx, AlarmId::ArcRadiusTolerance,
                 fmt::format("R{:g} cannot reach the end point: half the "
                             "distance to it is {:.4f}",
                             radius / ctx.scale(), half / ctx.scale()));
  }
  return 0;
}

namespace {

mbrt_status moveArc(mbrt_ctx& ctx, const MotionWords& words,
                    const AxisCounts& start, const AxisCounts& target) {
  const PlaneAxes plane = planeAxes(ctx.machine.modal.plane);
  const auto [p, q] = planeIndex(ctx);
  if (p < 0 || q < 0) {
    return raise(ctx, AlarmId::IllegalPlaneSelect,
                 fmt::format("G{} arcs need axes {} and {}",
                             ctx.machine.modal.plane, plane.letters[0],
                             plane.letters[1]));
  }
  const bool clockwise = ctx.machine.modal.motion == 2;
  const Point from{static_cast<double>(start[p]),
                   static_cast<double>(start[q])};
  const Point to{static_cast<double>(target[p]),
                 static_cast<double>(target[q])};
  if (words.hasR && from.x == to.x && from.y == to.y) {
    return 0; // FANUC: R with start == end makes no motion at all
  }
  if (const mbrt_status status =
          checkRadiusReaches(ctx, words, start, target)) {
    return status;
  }
  const std::optional<Point> found =
      arcCenter(ctx, words, start, target, clockwise);
  if (!found && ctx.profile.parameterBit(3403, 5)) {
    return raise(ctx, AlarmId::ArcNoRadius, "arc without R or I, J, K");
  }
  if (!found) {
    // Parameter 3403#5 CIR = 0 (FANUC's default): a straight feed move.
    return moveLine(ctx, target, false);
  }
  const Point center = *found;
  const double startRadius = std::hypot(from.x - center.x, from.y - center.y);
  if (!words.hasR) {
    if (const mbrt_status status = checkRadii(ctx, startRadius, to, center)) {
      return status;
    }
  }
  const ArcFrame frame = arcFrame(ctx, p, q);
  if (!frame.supported) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("G{:02} in G{} under unequal scaling or a "
                             "rotation in another plane",
                             ctx.machine.modal.motion,
                             ctx.machine.modal.plane));
  }
  AxisValues centerPoint{};
  centerPoint[p] = center.x;
  centerPoint[q] = center.y;
  Point workCenter = planePoint(ctx.machine.frames.transforms()
                                    ? transformPoint(ctx, centerPoint)
                                    : centerPoint,
                                p, q);
  workCenter.x += static_cast<double>(ctx.machine.frames.local[p]);
  workCenter.y += static_cast<double>(ctx.machine.frames.local[q]);
  const bool turnsClockwise = clockwise != frame.reversed;
  const AxisCounts work = programToWork(ctx, target);
  if (compensating(ctx)) {
    HeldMove move;
    move.arc = true;
    move.clockwise = turnsClockwise;
    move.start = programToWork(ctx, start);
    move.end = work;
    move.center[0] = workCenter.x;
    move.center[1] = workCenter.y;
    ctx.machine.program = target;
    return compensateMove(ctx, std::move(move));
  }
  const double radius = startRadius * frame.scale;
  const double sweep = sweepBetween(from, to, center, clockwise);
  const double arc = radius * sweep;
  const AxisCounts machine = workToMachine(ctx, work);
  const MoveOrigin origin = blockOrigin(ctx);
  const AxisCounts workStart = machineToWork(ctx, ctx.machine.position);
  const Point startPoint{static_cast<double>(workStart[p]),
                         static_cast<double>(workStart[q])};
  advanceClock(
      ctx,
      travel(ctx, machine, (std::uint32_t{1} << p) | (std::uint32_t{1} << q),
             arc),
      false, arc / ctx.scale(), origin,
      arcTurnMinutes(ctx, origin,
                     {p, q, workCenter, startPoint, sweep, turnsClockwise},
                     workStart));
  ctx.machine.program = target;
  moveTo(ctx, turnsClockwise ? MBRT_MOTION_CW : MBRT_MOTION_CCW, work, machine,
         workCenter, origin);
  widenBoxByArc(ctx, p, q, workCenter, startPoint, radius, sweep,
                turnsClockwise);
  return 0;
}

} // namespace

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

namespace {

/// Below these a feed per minute (mm/min, inch/min) is a lathe's feed per
/// revolution (F0.2): a mill would crawl.
constexpr double kLeastFeed[2] = {1.0, 0.04};

mbrt_status refuseFeedPerRevolution(mbrt_ctx& ctx) {
  return raise(ctx, AlarmId::Unsupported,
               fmt::format("F{} per minute: a lathe's feed per revolution "
                           "(G99 F{}; on a mill G95 feeds per revolution); "
                           "a lathe profile has \"series\": \"T\"",
                           ctx.machine.modal.feed, ctx.machine.modal.feed));
}

/// PS0011 for a feed move without F (in G93 without F in its block, in G95
/// without S); `cycle` names the canned cycle; a feed per minute too small
/// for a mill stops the run (refuseFeedPerRevolution).
mbrt_status checkFeed(mbrt_ctx& ctx, int cycle) {
  if (readingShape(ctx)) {
    return 0; // a shape's moves are read, not made
  }
  if (ctx.machine.modal.feedMode == 93 && !ctx.machine.feedInBlock) {
    return raise(ctx, AlarmId::FeedZero, "G93 needs F in every feed block");
  }
  const bool perRevolution =
      ctx.machine.modal.feedMode == 95 || cutsThread(ctx.machine.modal.motion);
  if (perRevolution &&
      ctx.machine.lastWords[lastWordSlot(LastWord::S)] <= 0.0) {
    return raise(ctx, AlarmId::FeedZero,
                 cutsThread(ctx.machine.modal.motion)
                     ? "threading needs a spindle speed (S)"
                 : ctx.profile.lathe()
                     ? fmt::format("feed per revolution (G{}) needs a "
                                   "spindle speed (S)",
                                   writtenLatheCode(ctx, 950))
                     : std::string("G95 needs a spindle speed (S)"));
  }
  if (ctx.machine.modal.feed > 0.0) {
    return ctx.machine.modal.feedMode != 94 || ctx.profile.lathe() ||
                   ctx.machine.modal.feed >= kLeastFeed[ctx.machine.modal.inch]
               ? 0
               : refuseFeedPerRevolution(ctx);
  }
  return raise(ctx, AlarmId::FeedZero,
               cycle != 0 ? fmt::format("G{} needs F greater than 0", cycle)
                          : fmt::format("G{:02} needs F greater than 0",
                                        ctx.machine.modal.motion));
}

/// A straight move of the control point to `machine`.
mbrt_status moveToMachine(mbrt_ctx& ctx, const AxisCounts& work,
                          const AxisCounts& machine, bool rapid, int cycle) {
  if (!rapid) {
    if (const mbrt_status status = checkFeed(ctx, cycle)) {
      return status;
    }
  }
  const MoveOrigin origin = blockOrigin(ctx, cycle);
  const Travel length = travel(ctx, machine, 0, 0.0);
  advanceClock(ctx, length, rapid, length.units, origin,
               rapid ? 0.0
                     : lineTurnMinutes(ctx, origin,
                                       machineToWork(ctx, ctx.machine.position),
                                       work));
  moveTo(ctx, rapid ? MBRT_MOTION_RAPID : MBRT_MOTION_LINEAR, work, machine,
         {0, 0}, origin);
  return 0;
}

/// A rapid to machine coordinates on the axes in `mask`, when it moves.
mbrt_status rapidInMachineCoordinates(mbrt_ctx& ctx, std::uint32_t mask,
                                      const AxisCounts& position) {
  AxisCounts machine = ctx.machine.position;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((mask >> axis & 1) != 0) {
      machine[axis] = position[axis];
    }
  }
  if (machine == ctx.machine.position) {
    return 0;
  }
  const mbrt_status status =
      moveToMachine(ctx, machineToWork(ctx, machine), machine, true, 0);
  const AxisCounts programmed = ctx.machine.program;
  resyncProgram(ctx);
  if (ctx.compensation->engaged) {
    // The tool stands on its vector: in the plane the program position is
    // still the programmed point.
    const PlaneIndex plane = planeIndex(ctx);
    ctx.machine.program[plane.p] = programmed[plane.p];
    ctx.machine.program[plane.q] = programmed[plane.q];
  }
  return status;
}

} // namespace

const AxisCounts& programPosition(const mbrt_ctx& ctx) {
  return ctx.machine.program;
}

void moveWorkStraight(mbrt_ctx& ctx, const AxisCounts& work, bool rapid,
                      const MoveOrigin& origin) {
  const AxisCounts machine = workToMachine(ctx, work);
  const Travel length = travel(ctx, machine, 0, 0.0);
  advanceClock(ctx, length, rapid, length.units, origin,
               rapid ? 0.0
                     : lineTurnMinutes(ctx, origin,
                                       machineToWork(ctx, ctx.machine.position),
                                       work));
  moveTo(ctx, rapid ? MBRT_MOTION_RAPID : MBRT_MOTION_LINEAR, work, machine,
         {0, 0}, origin);
}

void moveWorkArc(mbrt_ctx& ctx, const AxisCounts& work, PlanePoint center,
                 bool clockwise, const MoveOrigin& origin) {
  const auto [p, q] = planeIndex(ctx);
  const AxisCounts workStart = machineToWork(ctx, ctx.machine.position);
  const Point from{static_cast<double>(workStart[p]),
                   static_cast<double>(workStart[q])};
  const Point to{static_cast<double>(work[p]), static_cast<double>(work[q])};
  const double radius = std::hypot(from.x - center.x, from.y - center.y);
  const double sweep = sweepBetween(from, to, center, clockwise);
  const AxisCounts machine = workToMachine(ctx, work);
  advanceClock(
      ctx,
      travel(ctx, machine, (std::uint32_t{1} << p) | (std::uint32_t{1} << q),
             radius * sweep),
      false, radius * sweep / ctx.scale(), origin,
      arcTurnMinutes(ctx, origin, {p, q, center, from, sweep, clockwise},
                     workStart));
  moveTo(ctx, clockwise ? MBRT_MOTION_CW : MBRT_MOTION_CCW, work, machine,
         center, origin);
  widenBoxByArc(ctx, p, q, center, from, radius, sweep, clockwise);
}

mbrt_status moveStraight(mbrt_ctx& ctx, const AxisCounts& target, bool rapid,
                         int cycle) {
  const AxisCounts work = programToWork(ctx, target);
  ctx.machine.program = target;
  return moveToMachine(ctx, work, workToMachine(ctx, work), rapid, cycle);
}

mbrt_status moveToFrame(mbrt_ctx& ctx) {
  if (compensating(ctx)) { // a move without motion in the plane
    return compensateMove(ctx, straightTo(ctx, ctx.machine.program,
                                          ctx.machine.modal.motion == 0));
  }
  const AxisCounts work = programToWork(ctx, ctx.machine.program);
  const AxisCounts machine = workToMachine(ctx, work);
  if (machine == ctx.machine.position) {
    return 0;
  }
  return moveToMachine(ctx, work, machine, ctx.machine.modal.motion == 0, 0);
}

mbrt_status returnToReference(mbrt_ctx& ctx, const MotionWords& words,
                              int reference) {
  const AxisCounts intermediate = workTarget(ctx, words, ctx.machine.program);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((words.axisMask >> axis & 1) != 0) {
      ctx.machine.intermediate[axis] = intermediate[axis];
    }
  }
  ctx.machine.intermediateMask |= words.axisMask;
  const AxisCounts work = programToWork(ctx, intermediate);
  const bool compensated = ctx.compensation->engaged;
  if (const mbrt_status status = leaveOffsetAt(ctx, intermediate)) {
    return status;
  }
  if (!compensated && workToMachine(ctx, work) != ctx.machine.position) {
    if (const mbrt_status status = moveStraight(ctx, intermediate, true)) {
      return status;
    }
  }
  AxisCounts position{};
  if (reference > 1) {
    for (int axis = 0; axis < ctx.axisCount(); ++axis) {
      position[axis] = static_cast<Counts>(
          roundHalfAway(ctx.profile.axisParameter(1239 + reference, axis) *
                        ctx.countsPerMm()));
    }
  }
  return rapidInMachineCoordinates(ctx, words.axisMask, position);
}

mbrt_status returnFromReference(mbrt_ctx& ctx, const MotionWords& words) {
  const std::uint32_t mask = words.axisMask & ctx.machine.intermediateMask;
  AxisCounts through = ctx.machine.program;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((mask >> axis & 1) != 0) {
      through[axis] = ctx.machine.intermediate[axis];
    }
  }
  if (const mbrt_status status = leaveOffsetAt(ctx, through)) {
    return status;
  }
  if (through != ctx.machine.program) {
    if (const mbrt_status status = moveStraight(ctx, through, true)) {
      return status;
    }
  }
  // In G91 the words count from the intermediate point. Under cutter
  // compensation this move starts it again.
  return moveLine(ctx, workTarget(ctx, words, ctx.machine.program), true);
}

namespace {

/// The stylus ball centre, mm: the control point less the tool length.
Point3 tipOf(const mbrt_ctx& ctx, const AxisCounts& machine) {
  Point3 tip{};
  for (int i = 0; i < 3; ++i) {
    const int axis = ctx.axisOf(static_cast<char>('X' + i));
    if (axis >= 0) {
      const Counts length =
          axis == ctx.machine.frames.lengthAxis ? ctx.machine.frames.length : 0;
      tip[i] = static_cast<double>(machine[axis] - length) / ctx.countsPerMm();
    }
  }
  return tip;
}

} // namespace

mbrt_status skipMove(mbrt_ctx& ctx, const MotionWords& words, double p) {
  constexpr int kSkipCode = 31;
  if (!(p >= 1.0 && p <= kSkipSignals)) {
    return raise(
        ctx, AlarmId::ImproperNcAddress,
        fmt::format("G31 P{}: the skip signal is P1 to P{}", p, kSkipSignals));
  }
  const int signal = static_cast<int>(p);
  if (const mbrt_status status = checkFeed(ctx, kSkipCode)) {
    return status;
  }
  const AxisCounts target = workTarget(ctx, words, ctx.machine.program);
  const AxisCounts machine = workToMachine(ctx, programToWork(ctx, target));
  const std::optional<double> contact =
      firstContact(ctx.profile.probe, tipOf(ctx, ctx.machine.position),
                   tipOf(ctx, machine), signal);
  mbrt_status status = 0;
  if (contact) {
    AxisCounts stop = ctx.machine.position;
    for (int axis = 0; axis < ctx.axisCount(); ++axis) {
      stop[axis] += static_cast<Counts>(roundHalfAway(
          *contact *
          static_cast<double>(machine[axis] - ctx.machine.position[axis])));
    }
    status = moveToMachine(ctx, machineToWork(ctx, stop), stop, false, 0);
    resyncProgram(ctx);
  } else {
    status = moveStraight(ctx, target, false);
  }
  ctx.machine.skipPosition = localPosition(ctx);
  return status;
}

mbrt_status moveInMachineCoordinates(mbrt_ctx& ctx, const MotionWords& words) {
  if (ctx.machine.modal.incremental) {
    return 0;
  }
  if (const mbrt_status status = suspendCompensation(ctx, words.axisMask)) {
    return status;
  }
  return rapidInMachineCoordinates(ctx, words.axisMask, words.axis);
}

void dwell(mbrt_ctx& ctx, double seconds) {
  passTime(ctx, seconds);
}

mbrt_status moveLine(mbrt_ctx& ctx, const AxisCounts& target, bool rapid,
                     const MotionWords* words) {
  if (!compensating(ctx)) {
    return moveStraight(ctx, target, rapid);
  }
  if (!rapid) {
    if (const mbrt_status status = checkFeed(ctx, 0)) {
      return status;
    }
  }
  HeldMove move = straightTo(ctx, target, rapid);
  if (words != nullptr && words->centerMask != 0 &&
      ctx.compensation->codeInBlock) {
    readVectorDirection(ctx, *words, move);
  }
  return compensateMove(ctx, std::move(move));
}

mbrt_status moveArcAbout(mbrt_ctx& ctx, const AxisCounts& end,
                         const AxisCounts& center, bool clockwise) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlaneAxes axes = planeAxes(ctx.machine.modal.plane);
  MotionWords words;
  words.axisMask =
      (std::uint32_t{1} << plane.p) | (std::uint32_t{1} << plane.q);
  words.axis = end;
  for (int i = 0; i < 2; ++i) {
    const int axis = i == 0 ? plane.p : plane.q;
    const int index = axes.centerIndex[i];
    words.centerMask |= std::uint32_t{1} << index;
    words.center[static_cast<std::size_t>(index)] =
        center[axis] - ctx.machine.program[axis];
  }
  const ModalState modal = ctx.machine.modal;
  ctx.machine.modal.motion = clockwise ? 2 : 3;
  ctx.machine.modal.incremental = false;
  const mbrt_status status = executeMotion(ctx, words);
  ctx.machine.modal.motion = modal.motion;
  ctx.machine.modal.incremental = modal.incremental;
  return status;
}

namespace {

/// G34's K (a length per revolution) into ctx.machine.leadChange; PS0014 when
/// the lead would shrink to nothing before the thread's end.
mbrt_status readLeadChange(mbrt_ctx& ctx, const MotionWords& words,
                           const AxisCounts& target) {
  const bool hasK = (words.centerMask >> 2 & 1) != 0;
  ctx.machine.leadChange =
      hasK ? static_cast<double>(words.center[2]) / ctx.scale() : 0.0;
  double longest = 0.0; // the thread's length along its longer axis
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (!ctx.isRotary(axis)) {
      longest =
          std::max(longest, std::fabs(static_cast<double>(
                                target[axis] - ctx.machine.program[axis])) /
                                ctx.scale());
    }
  }
  const double lead = ctx.machine.modal.feed;
  if (lead * lead + 2.0 * ctx.machine.leadChange * longest <= 0.0) {
    return raise(ctx, AlarmId::IllegalLeadCommand,
                 fmt::format("G34 F{} K{}: the lead shrinks to 0 before the "
                             "thread's end, {} long",
                             lead, ctx.machine.leadChange, longest));
  }
  return 0;
}

} // namespace

mbrt_status executeMotion(mbrt_ctx& ctx, const MotionWords& words) {
  const int mode = ctx.machine.modal.motion;
  const AxisCounts start = ctx.machine.program;
  AxisCounts target = workTarget(ctx, words, start);
  if (words.angle && !(ctx.corner->pending && ctx.corner->openEnd)) {
    if (const mbrt_status status = endAngledLine(ctx, words, start, target)) {
      return status;
    }
  }
  if (ctx.corner->pending) {
    return moveAfterCorner(ctx, words, target);
  }
  if (hasCommaWords(words) && holdsForNextBlock(ctx, words)) {
    return holdBlendMove(ctx, words, start, target);
  }
  if (mode == 1 && ctx.profile.lathe() && insertsCorner(ctx, words)) {
    return holdCornerMove(ctx, words, start, target);
  }
  if (mode == kVariableLeadMotion) {
    if (const mbrt_status status = readLeadChange(ctx, words, target)) {
      return status;
    }
  }
  if (mode == 0 || mode == 1 || mode == kThreadingMotion ||
      mode == kVariableLeadMotion) {
    return moveLine(ctx, target, mode == 0, &words);
  }
  if (isSingleCycle(mode)) {
    return executeSingleCycle(ctx, words);
  }
  if (const mbrt_status status = checkFeed(ctx, 0)) {
    return status;
  }
  return moveArc(ctx, words, start, target);
}

} // namespace mbc::rt
