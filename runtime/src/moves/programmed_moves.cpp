// Programmed moves (programmed_moves.h): end points and arc centres from a
// block's words, feeds, G28-G31 and G53, each through cutter compensation
// when it is on, else straight to the tool moves.
#include "programmed_moves.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cutter_comp.h"
#include "cutter_comp_state.h"
#include "frames.h"
#include "lathe_codes.h"
#include "tool_moves.h"

namespace mbc::rt {

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
  if (ctx.run.readingShape()) {
    return 0; // a shape's moves are read, not made
  }
  if (ctx.machine.modal.feedMode == 93 && !ctx.machine.feedInBlock) {
    return raise(ctx, AlarmId::FeedZero, "G93 needs F in every feed block");
  }
  const bool perRevolution =
      ctx.machine.modal.feedMode == 95 || cutsThread(ctx.machine.modal.motion);
  if (perRevolution &&
      ctx.machine.lastWords[lastWordSlot(LastWord::S)] <= 0.0) {
    return raise(
        ctx, AlarmId::FeedZero,
        cutsThread(ctx.machine.modal.motion)
            ? "threading needs a spindle speed (S)"
        : ctx.profile.lathe()
            ? fmt::format("feed per revolution (G{}) needs a "
                          "spindle speed (S)",
                          writtenLatheCode(ctx.profile.gCodeSystem, 950))
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
  return moveStraightTo(ctx, work, machine, rapid, blockOrigin(ctx, cycle));
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

mbrt_status moveArcFrom(mbrt_ctx& ctx, const MotionWords& words,
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
  const MoveOrigin origin = blockOrigin(ctx);
  ctx.machine.program = target;
  return moveArcTo(ctx, work, workCenter, startRadius * frame.scale,
                   sweepBetween(from, to, center, clockwise), turnsClockwise,
                   origin);
}

} // namespace

mbrt_status moveArc(mbrt_ctx& ctx, const MotionWords& words,
                    const AxisCounts& start, const AxisCounts& target) {
  if (const mbrt_status status = checkFeed(ctx, 0)) {
    return status;
  }
  return moveArcFrom(ctx, words, start, target);
}

mbrt_status moveStraight(mbrt_ctx& ctx, const AxisCounts& target, bool rapid,
                         int cycle) {
  AxisCounts work;
  AxisCounts machine;
  placeProgramPoint(ctx, target, work, machine);
  ctx.machine.program = target;
  return moveToMachine(ctx, work, machine, rapid, cycle);
}

mbrt_status moveToFrame(mbrt_ctx& ctx) {
  if (compensating(ctx)) { // a move without motion in the plane
    return compensateMove(ctx, straightTo(ctx, ctx.machine.program,
                                          ctx.machine.modal.motion == 0));
  }
  AxisCounts work;
  AxisCounts machine;
  placeProgramPoint(ctx, ctx.machine.program, work, machine);
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
  const AxisCounts start = ctx.machine.program;
  const mbrt_status status =
      moveArc(ctx, words, start, workTarget(ctx, words, start));
  ctx.machine.modal.motion = modal.motion;
  ctx.machine.modal.incremental = modal.incremental;
  return status;
}

} // namespace mbc::rt
