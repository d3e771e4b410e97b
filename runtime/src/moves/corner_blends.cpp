// Chamfering and corner R at any angle, and ,A lines (corner_blends.h).
#include "corner_blends.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "corner_state.h"
#include "held_block.h"
#include "programmed_moves.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

/// Points closer than this many counts are one point: a corner computed in
/// double lands within rounding of where the program put it.
constexpr double kSamePoint = 0.5;

/// One move in the plane (program counts): a line, or an arc about
/// `center`.
struct PlaneMove {
  PlanePoint start{};
  PlanePoint end{};
  bool arc = false;
  bool clockwise = false;
  PlanePoint center{};
};

PlanePoint planeOf(const AxisCounts& point, PlaneIndex plane) {
  return {static_cast<double>(point[plane.p]),
          static_cast<double>(point[plane.q])};
}

/// `point` with its plane axes at `at`, rounded to counts.
AxisCounts withPlane(AxisCounts point, PlaneIndex plane, PlanePoint at) {
  point[plane.p] = static_cast<Counts>(roundHalfAway(at.x));
  point[plane.q] = static_cast<Counts>(roundHalfAway(at.y));
  return point;
}

/// The plane's two axes as a mask of axis words; none when the machine
/// lacks one of them.
std::uint32_t planeBits(PlaneIndex plane) {
  if (plane.p < 0 || plane.q < 0) {
    return 0;
  }
  return (std::uint32_t{1} << plane.p) | (std::uint32_t{1} << plane.q);
}

/// A ,A line that gives neither coordinate of the plane: the next block
/// gives its end point.
bool opensAngledLine(const MotionWords& words, PlaneIndex plane) {
  return words.angle && (words.axisMask & planeBits(plane)) == 0;
}

/// Whether `to` differs from `from` on an axis out of the plane.
bool leavesPlane(const mbrt_ctx& ctx, const AxisCounts& from,
                 const AxisCounts& to, PlaneIndex plane) {
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (axis != plane.p && axis != plane.q && from[axis] != to[axis]) {
      return true;
    }
  }
  return false;
}

double radiusOf(const PlaneMove& move) {
  return length(move.start - move.center);
}

/// The direction of travel at `at`, a point of the move.
PlanePoint tangentAt(const PlaneMove& move, PlanePoint at) {
  if (!move.arc) {
    return unit(move.end - move.start);
  }
  const PlanePoint radial = unit(at - move.center);
  return move.clockwise ? PlanePoint{radial.y, -radial.x} : leftOf(radial);
}

/// How far along the move `at` (a point on its line or circle) lies from
/// the start: a length on a line, a sweep on an arc.
double travelTo(const PlaneMove& move, PlanePoint at) {
  if (length(at - move.start) < kSamePoint) {
    return 0.0;
  }
  if (!move.arc) {
    return dot(at - move.start, unit(move.end - move.start));
  }
  return sweepBetween(move.start, at, move.center, move.clockwise);
}

double travelOf(const PlaneMove& move) {
  return move.arc
             ? sweepBetween(move.start, move.end, move.center, move.clockwise)
             : length(move.end - move.start);
}

/// Whether `at` lies on the move between its start and end.
bool within(const PlaneMove& move, PlanePoint at) {
  if (length(at - move.end) < kSamePoint) {
    return true;
  }
  const double tolerance = move.arc ? kSamePoint / radiusOf(move) : kSamePoint;
  const double travel = travelTo(move, at);
  return travel >= -tolerance && travel <= travelOf(move) + tolerance;
}

/// The line or circle the move runs on, moved `by` counts to its left
/// side (negative: right).
PlaneCurve offsetCurve(const PlaneMove& move, double by) {
  PlaneCurve curve;
  if (!move.arc) {
    curve.direction = unit(move.end - move.start);
    curve.point = move.start + by * leftOf(curve.direction);
    return curve;
  }
  curve.circle = true;
  curve.center = move.center;
  // The left of a counter-clockwise arc is its centre.
  curve.radius = radiusOf(move) + (move.clockwise ? by : -by);
  return curve;
}

/// The point of `move` nearest `point`, on its line or circle.
PlanePoint footOn(const PlaneMove& move, PlanePoint point) {
  if (!move.arc) {
    const PlanePoint direction = unit(move.end - move.start);
    return move.start + dot(point - move.start, direction) * direction;
  }
  return move.center + radiusOf(move) * unit(point - move.center);
}

/// The point of `move` at the straight distance `amount` from its end
/// (`fromEnd`) or its start, on the move; none when it is shorter.
std::optional<PlanePoint> pointAtDistance(const PlaneMove& move, double amount,
                                          bool fromEnd) {
  const PlanePoint corner = fromEnd ? move.end : move.start;
  if (!move.arc) {
    const PlanePoint direction = unit(move.end - move.start);
    if (amount > length(move.end - move.start) + kSamePoint) {
      return std::nullopt;
    }
    return fromEnd ? corner - amount * direction : corner + amount * direction;
  }
  PlaneCurve circle;
  circle.circle = true;
  circle.center = move.center;
  circle.radius = radiusOf(move);
  PlaneCurve around;
  around.circle = true;
  around.center = corner;
  around.radius = amount;
  std::optional<PlanePoint> best;
  double bestTravel = 0.0;
  for (const PlanePoint& at : intersections(circle, around)) {
    if (!within(move, at)) {
      continue;
    }
    // Of two points on the move, the one nearer the corner along it.
    const double travel = travelTo(move, at);
    if (!best || (fromEnd ? travel > bestTravel : travel < bestTravel)) {
      best = at;
      bestTravel = travel;
    }
  }
  return best;
}

/// Where the inserted chamfer or arc leaves the first move and joins the
/// second, and the arc's centre.
struct Blend {
  PlanePoint leave{};
  PlanePoint join{};
  PlanePoint center{};
  bool clockwise = false;
};

std::string amountText(const mbrt_ctx& ctx, char blend, double amount) {
  return fmt::format("{} of {:g}", blend == 'C' ? "chamfer" : "corner R",
                     amount / ctx.scale());
}

mbrt_status tooShort(mbrt_ctx& ctx, const CornerInsertion& held,
                     std::string_view which) {
  return raise(
      ctx, AlarmId::MissingCornerMove,
      fmt::format("{} is shorter than the {} of line {}", which,
                  amountText(ctx, held.blend, static_cast<double>(held.amount)),
                  held.line));
}

mbrt_status chamferPoints(mbrt_ctx& ctx, const CornerInsertion& held,
                          const PlaneMove& first, const PlaneMove& second,
                          Blend& blend) {
  const auto amount = static_cast<double>(held.amount);
  const std::optional<PlanePoint> leave = pointAtDistance(first, amount, true);
  if (!leave) {
    return tooShort(ctx, held, "the move of that block");
  }
  const std::optional<PlanePoint> join = pointAtDistance(second, amount, false);
  if (!join) {
    return tooShort(ctx, held, "the next move");
  }
  blend.leave = *leave;
  blend.join = *join;
  return 0;
}

mbrt_status roundPoints(mbrt_ctx& ctx, const CornerInsertion& held,
                        const PlaneMove& first, const PlaneMove& second,
                        Blend& blend) {
  const PlanePoint corner = first.end;
  const double turn =
      cross(tangentAt(first, corner), tangentAt(second, corner));
  if (std::fabs(turn) < 1e-9) {
    return raise(ctx, AlarmId::MissingCornerMove,
                 fmt::format("the moves meet in a straight or tangent line: "
                             "the corner R of line {} has no corner",
                             held.line));
  }
  // The arc's centre lies inside the turn, `r` from both moves.
  const auto radius = static_cast<double>(held.amount);
  const double side = turn > 0.0 ? radius : -radius;
  const PlaneCurve a = offsetCurve(first, side);
  const PlaneCurve b = offsetCurve(second, side);
  if ((a.circle && a.radius <= 0.0) || (b.circle && b.radius <= 0.0)) {
    return tooShort(ctx, held, "the radius of an arc");
  }
  std::optional<Blend> best;
  for (const PlanePoint& center : intersections(a, b)) {
    const PlanePoint leave = footOn(first, center);
    const PlanePoint join = footOn(second, center);
    if (!within(first, leave) || !within(second, join)) {
      continue;
    }
    if (!best || length(center - corner) < length(best->center - corner)) {
      best = Blend{leave, join, center, turn < 0.0};
    }
  }
  if (!best) {
    return tooShort(ctx, held, "a move at that corner");
  }
  blend = *best;
  return 0;
}

/// The move from the program position along `move`'s line or circle to
/// `end`; nothing when it is already there.
mbrt_status runAlong(mbrt_ctx& ctx, const PlaneMove& move,
                     const AxisCounts& end, bool rapid) {
  if (end == ctx.machine.program) {
    return 0;
  }
  if (!move.arc) {
    return moveLine(ctx, end, rapid);
  }
  return moveArcAbout(ctx, end, withPlane(end, planeIndex(ctx), move.center),
                      move.clockwise);
}

PlaneMove heldMove(const CornerInsertion& held, PlaneIndex plane) {
  return {planeOf(held.from, plane), planeOf(held.corner, plane), held.arc,
          held.clockwise, PlanePoint{held.center[0], held.center[1]}};
}

/// The move of the block now running, from `start` to `target` in the modal
/// mode: an arc about the centre its words give, or a line.
mbrt_status blockMove(mbrt_ctx& ctx, const MotionWords& words,
                      const AxisCounts& start, const AxisCounts& target,
                      PlaneMove& move) {
  const PlaneIndex plane = planeIndex(ctx);
  move.start = planeOf(start, plane);
  move.end = planeOf(target, plane);
  const int mode = ctx.machine.modal.motion;
  if (mode != 2 && mode != 3) {
    return 0;
  }
  if (const mbrt_status status =
          checkRadiusReaches(ctx, words, start, target)) {
    return status;
  }
  const std::optional<PlanePoint> center =
      arcCenter(ctx, words, start, target, mode == 2);
  if (!center && ctx.profile.parameterBit(3403, 5)) {
    return raise(ctx, AlarmId::ArcNoRadius, "arc without R or I, J, K");
  }
  if (center && length(move.end - move.start) < kSamePoint) {
    return raise(ctx, AlarmId::Unsupported,
                 "a chamfer or corner R at the end of a full circle");
  }
  move.arc = center.has_value();
  move.clockwise = mode == 2;
  move.center = center.value_or(PlanePoint{});
  return 0;
}

mbrt_status outOfPlane(mbrt_ctx& ctx) {
  return raise(ctx, AlarmId::Unsupported,
               "a chamfer, corner R or ,A line that moves an axis out of the "
               "plane (G17, G18, G19)");
}

/// Runs the held move up to the chamfer or arc, and the chamfer or arc;
/// this block's `second` move then goes on from where it joins.
mbrt_status insertBlend(mbrt_ctx& ctx, const CornerInsertion& held,
                        const PlaneMove& second, Blend& blend) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlaneMove first = heldMove(held, plane);
  if (const mbrt_status status =
          held.blend == 'C' ? chamferPoints(ctx, held, first, second, blend)
                            : roundPoints(ctx, held, first, second, blend)) {
    return status;
  }
  const AxisCounts leave = withPlane(held.corner, plane, blend.leave);
  const AxisCounts join = withPlane(held.corner, plane, blend.join);
  ctx.machine.program = held.from;
  return asHeldBlock(ctx, held, [&] {
    if (const mbrt_status status = runAlong(ctx, first, leave, false)) {
      return status;
    }
    if (held.blend == 'C' || join == leave) {
      return join == leave ? 0 : moveLine(ctx, join, false);
    }
    return moveArcAbout(ctx, join, withPlane(join, plane, blend.center),
                        blend.clockwise);
  });
}

/// The corner of an open ,A line (held) and this block's end point
/// `target` with its ,A: where the two lines meet.
mbrt_status closeAngledLine(mbrt_ctx& ctx, CornerInsertion& held,
                            const MotionWords& words,
                            const AxisCounts& target) {
  const PlaneIndex plane = planeIndex(ctx);
  const int mode = ctx.machine.modal.motion;
  if (mode != 0 && mode != 1) {
    return raise(ctx, AlarmId::NotG01AfterCorner,
                 fmt::format("the block after the ,A line of line {} must be "
                             "a G01 line",
                             held.line));
  }
  if (!words.angle || (words.axisMask & planeBits(plane)) != planeBits(plane)) {
    return raise(ctx, AlarmId::NoEndPointAndAngle,
                 fmt::format("the ,A line of line {} has no end point: this "
                             "block gives the end point of the next line, "
                             "both coordinates, and its ,A",
                             held.line));
  }
  if (leavesPlane(ctx, held.from, target, plane)) {
    return outOfPlane(ctx);
  }
  const double first = held.angle * std::numbers::pi / 180.0;
  const double second = *words.angle * std::numbers::pi / 180.0;
  PlaneCurve a;
  a.point = planeOf(held.from, plane);
  a.direction = {std::cos(first), std::sin(first)};
  PlaneCurve b;
  b.point = planeOf(target, plane);
  b.direction = {std::cos(second), std::sin(second)};
  const std::vector<PlanePoint> corner = intersections(a, b);
  if (corner.empty()) {
    return raise(ctx, AlarmId::NoSolutionOfBlockEnd,
                 fmt::format(",A{:g} of line {} and ,A{:g} are parallel: the "
                             "lines never meet",
                             held.angle, held.line, *words.angle));
  }
  held.corner = withPlane(held.from, plane, corner.front());
  held.openEnd = false;
  return 0;
}

/// Holds the block's `move` (its line or circle) from `start` to `target`
/// for the next block; `open`: a ,A line without its end point.
void holdMove(mbrt_ctx& ctx, const MotionWords& words, const AxisCounts& start,
              const AxisCounts& target, const PlaneMove& move, bool open) {
  CornerInsertion& held = *ctx.corner;
  held = CornerInsertion{};
  held.pending = true;
  held.fresh = true;
  held.from = start;
  held.corner = target;
  held.amount = words.blendAmount;
  held.file = ctx.run.block.file;
  held.line = ctx.run.block.line;
  held.block = captureBlock(ctx);
  held.blend = words.blend;
  held.rapid = ctx.machine.modal.motion == 0;
  held.arc = move.arc;
  held.clockwise = move.clockwise;
  held.center = {move.center.x, move.center.y};
  held.openEnd = open;
  held.angle = words.angle.value_or(0.0);
  if (!open) {
    ctx.machine.program = target;
  }
}

} // namespace

mbrt_status missingPlaneAxis(mbrt_ctx& ctx) {
  return raise(ctx, AlarmId::IllegalPlaneSelect,
               fmt::format("chamfering, corner R and ,A in G{} need both "
                           "axes of the plane",
                           ctx.machine.modal.plane));
}

bool holdsForNextBlock(const mbrt_ctx& ctx, const MotionWords& words) {
  return words.blend != 0 || opensAngledLine(words, planeIndex(ctx));
}

mbrt_status endAngledLine(mbrt_ctx& ctx, const MotionWords& words,
                          const AxisCounts& start, AxisCounts& target) {
  const PlaneIndex plane = planeIndex(ctx);
  if (plane.p < 0 || plane.q < 0) {
    return missingPlaneAxis(ctx);
  }
  if (ctx.machine.modal.motion != 0 && ctx.machine.modal.motion != 1) {
    return raise(ctx, AlarmId::TooManyAddressCommands,
                 fmt::format(",A gives the angle of a G00 or G01 line, not "
                             "of G{:02}",
                             ctx.machine.modal.motion));
  }
  const bool p = (words.axisMask >> plane.p & 1) != 0;
  const bool q = (words.axisMask >> plane.q & 1) != 0;
  const char* axes = ctx.profile.axes.data();
  if (p && q) {
    return raise(ctx, AlarmId::TooManyAddressCommands,
                 fmt::format("{}, {} and ,A: the angle gives one of the two "
                             "coordinates",
                             axes[plane.p], axes[plane.q]));
  }
  if (!p && !q) {
    return 0;
  }
  const double angle = *words.angle * std::numbers::pi / 180.0;
  const double along = p ? std::cos(angle) : std::sin(angle);
  if (std::fabs(along) < 1e-9) {
    return raise(ctx, AlarmId::NoSolutionOfBlockEnd,
                 fmt::format("a line at ,A{:g} never reaches the {} given",
                             *words.angle, axes[p ? plane.p : plane.q]));
  }
  // The line from the start at the angle, to the coordinate given.
  const int given = p ? plane.p : plane.q;
  const int found = p ? plane.q : plane.p;
  const double distance =
      static_cast<double>(target[given] - start[given]) / along;
  const double across = p ? std::sin(angle) : std::cos(angle);
  target[found] =
      start[found] + static_cast<Counts>(roundHalfAway(distance * across));
  return 0;
}

mbrt_status holdBlendMove(mbrt_ctx& ctx, const MotionWords& words,
                          const AxisCounts& start, const AxisCounts& target) {
  const PlaneIndex plane = planeIndex(ctx);
  if (plane.p < 0 || plane.q < 0) {
    return missingPlaneAxis(ctx);
  }
  const int mode = ctx.machine.modal.motion;
  const bool open = opensAngledLine(words, plane);
  if (!open && mode != 1 && mode != 2 && mode != 3) {
    return raise(ctx, AlarmId::TooManyAddressCommands,
                 fmt::format(",{} ends a G01, G02 or G03 move, not G{:02}",
                             words.blend, mode));
  }
  if (leavesPlane(ctx, start, target, plane)) {
    return outOfPlane(ctx);
  }
  PlaneMove move;
  if (const mbrt_status status =
          open ? 0 : blockMove(ctx, words, start, target, move)) {
    return status;
  }
  holdMove(ctx, words, start, target, move, open);
  return 0;
}

mbrt_status moveAfterBlend(mbrt_ctx& ctx, const MotionWords& words,
                           const AxisCounts& target) {
  CornerInsertion held = *ctx.corner;
  ctx.corner->pending = false;
  const PlaneIndex plane = planeIndex(ctx);
  if (ctx.machine.modal.plane != held.block.modal.plane) {
    return raise(ctx, AlarmId::MissingMoveAfterCorner,
                 fmt::format("the block after the chamfer, corner R or ,A "
                             "line of line {} changes the plane (G{} to G{})",
                             held.line, held.block.modal.plane,
                             ctx.machine.modal.plane));
  }
  if (held.openEnd) {
    if (const mbrt_status status = closeAngledLine(ctx, held, words, target)) {
      return status;
    }
    if (held.blend == 0) {
      ctx.machine.program = held.from;
      if (const mbrt_status status = asHeldBlock(ctx, held, [&] {
            return moveLine(ctx, held.corner, held.rapid);
          })) {
        return status;
      }
      return words.blend != 0
                 ? holdBlendMove(ctx, words, held.corner, target)
                 : moveLine(ctx, target, ctx.machine.modal.motion == 0);
    }
  }
  const int mode = ctx.machine.modal.motion;
  if (mode != 1 && mode != 2 && mode != 3) {
    return raise(ctx, AlarmId::NotG01AfterCorner,
                 fmt::format("the block after a chamfer or corner R (line "
                             "{}) must be G01, G02 or G03",
                             held.line));
  }
  if (leavesPlane(ctx, held.corner, target, plane)) {
    return outOfPlane(ctx);
  }
  PlaneMove second;
  if (const mbrt_status status =
          blockMove(ctx, words, held.corner, target, second)) {
    return status;
  }
  if (length(second.end - second.start) < kSamePoint) {
    return raise(ctx, AlarmId::MissingMoveAfterCorner,
                 fmt::format("the block after a chamfer or corner R (line "
                             "{}) must move in the plane",
                             held.line));
  }
  Blend blend;
  if (const mbrt_status status = insertBlend(ctx, held, second, blend)) {
    return status;
  }
  // This move goes on from the join, on its own line or circle.
  const AxisCounts join = withPlane(held.corner, plane, blend.join);
  if (words.blend != 0) {
    holdMove(ctx, words, join, target, second, false);
    return 0;
  }
  return runAlong(ctx, second, target, false);
}

mbrt_status runHeldAsProgrammed(mbrt_ctx& ctx, const CornerInsertion& held) {
  if (held.openEnd) {
    return 0; // a line without an end point goes nowhere
  }
  ctx.machine.program = held.from;
  const PlaneMove move = heldMove(held, planeIndex(ctx));
  return asHeldBlock(
      ctx, held, [&] { return runAlong(ctx, move, held.corner, held.rapid); });
}

} // namespace mbc::rt
