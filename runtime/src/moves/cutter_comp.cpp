// Cutter compensation C as a FANUC 0i-F / 30i-B does it (docs/language.md
// "Cutter compensation"): the vector at the end of each move comes from the
// corner it makes with the next move in the plane. Inner corners take the
// intersection of the two offset paths; outer corners of 90 degrees or
// more the intersection of the tangents; sharper ones two vectors, each
// extended by the offset along its path and joined by a straight line. The
// start-up move (type A or B, 5003#0 SUP) and the cancel move follow the
// same figures, type A with a single vector perpendicular to the next or
// the previous move.
#include "cutter_comp.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <numbers>
#include <optional>
#include <vector>

#include "corner_state.h"
#include "cutter_comp_state.h"
#include "flat_gcode.h"
#include "frames.h"
#include "plane_geometry.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

/// Tool nose radius compensation's tool (G41/G42 on a lathe): the nose
/// radius of the offset in force (geometry, plus the wear while a wear
/// offset is selected) and the imaginary tip from the nose centre, by the
/// tip direction (1-8, X up and Z right; 0 and 9: the centre is
/// programmed).
struct NoseTool {
  Counts radius = 0;
  AxisCounts tip{};
};

NoseTool noseTool(const mbrt_ctx& ctx) {
  const Frames& frames = ctx.machine.frames;
  const LatheOffset& geometry =
      ctx.data
          .latheOffsets[static_cast<std::size_t>(frames.toolGeometryNumber)];
  const LatheOffset& wear =
      ctx.data.latheOffsets[static_cast<std::size_t>(frames.toolWearNumber)];
  const double radius =
      geometry.rGeometry + (frames.toolWearNumber != 0 ? wear.rWear : 0.0);
  NoseTool tool{static_cast<Counts>(roundToLengthCounts(ctx, radius)), {}};
  // Tip directions 1-8 (X up, Z right): the tip from the nose centre.
  static constexpr int kTip[9][2] = {{0, 0}, {1, 1}, {1, -1}, {-1, -1}, {-1, 1},
                                     {0, 1}, {1, 0}, {0, -1}, {-1, 0}};
  const auto tip = static_cast<int>(geometry.tip);
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  if (tip >= 1 && tip <= 8) {
    tool.tip[x] = kTip[tip][0] * tool.radius;
    tool.tip[z] = kTip[tip][1] * tool.radius;
  }
  return tool;
}

PlanePoint pointOf(const AxisCounts& position, PlaneIndex plane) {
  return {static_cast<double>(position[plane.p]),
          static_cast<double>(position[plane.q])};
}

/// A direction of the program (on the plane's axes) in the workpiece frame:
/// mirror, scaling and rotation turn it as they turn points.
PlanePoint workDirection(const mbrt_ctx& ctx, PlanePoint direction) {
  const PlaneIndex plane = planeIndex(ctx);
  AxisValues tip{};
  tip[plane.p] = direction.x;
  tip[plane.q] = direction.y;
  const AxisValues origin = transformPoint(ctx, AxisValues{});
  tip = transformPoint(ctx, tip);
  return {tip[plane.p] - origin[plane.p], tip[plane.q] - origin[plane.q]};
}

/// The I J K words of the plane, as a direction of the program.
PlanePoint centerWords(const mbrt_ctx& ctx, const MotionWords& words) {
  const PlaneAxes axes = planeAxes(ctx.machine.modal.plane);
  return {static_cast<double>(words.center[axes.centerIndex[0]]),
          static_cast<double>(words.center[axes.centerIndex[1]])};
}

/// Where the tool is, in the workpiece frame.
AxisCounts toolPosition(const mbrt_ctx& ctx) {
  return machineToWork(ctx, ctx.machine.position);
}

/// The move's end position with the plane axes at `point` (rounded to
/// counts): what the other axes do, they do on every piece of the move.
AxisCounts placeAt(const HeldMove& move, PlaneIndex plane, PlanePoint point) {
  AxisCounts position = move.end;
  position[plane.p] = static_cast<Counts>(roundHalfAway(point.x));
  position[plane.q] = static_cast<Counts>(roundHalfAway(point.y));
  return position;
}

PlanePoint centerOf(const HeldMove& move) {
  return {move.center[0], move.center[1]};
}

/// The direction of travel at a point of the programmed move.
PlanePoint tangentAt(const HeldMove& move, PlaneIndex plane, PlanePoint at) {
  if (!move.arc) {
    return unit(pointOf(move.end, plane) - pointOf(move.start, plane));
  }
  const PlanePoint radial = unit(at - centerOf(move));
  return move.clockwise ? PlanePoint{radial.y, -radial.x} : leftOf(radial);
}

/// The vector from the path to the tool centre where the path runs along
/// `tangent`: `offset` to the left (`side` 1) or the right (-1).
PlanePoint vectorAt(double offset, int side, PlanePoint tangent) {
  return (offset * side) * leftOf(tangent);
}

/// The vector of the side and offset the move is compensated with.
PlanePoint vectorAt(const HeldMove& move, PlanePoint tangent) {
  return vectorAt(move.offset, move.side, tangent);
}

/// The radius of the tool-centre path of an arc: the tool is inside the
/// arc when it is left of a counter-clockwise arc or right of a clockwise.
double offsetRadius(const HeldMove& move, PlaneIndex plane,
                    const HeldMove& by) {
  const double radius = length(pointOf(move.start, plane) - centerOf(move));
  const bool inside = (by.side > 0) != move.clockwise;
  return inside ? radius - by.offset : radius + by.offset;
}

/// The tool-centre path of a move, without its ends: a line through its
/// offset start or the circle of its offset radius, offset by the side and
/// value of `by` (a corner takes the vector of the move before it).
PlaneCurve offsetCurve(const HeldMove& move, PlaneIndex plane,
                       const HeldMove& by) {
  PlaneCurve curve;
  if (move.arc) {
    curve.circle = true;
    curve.center = centerOf(move);
    curve.radius = offsetRadius(move, plane, by);
    return curve;
  }
  const PlanePoint start = pointOf(move.start, plane);
  curve.direction = tangentAt(move, plane, start);
  curve.point = start + vectorAt(by, curve.direction);
  return curve;
}

/// The intersection nearest the corner, if the two paths meet.
std::optional<PlanePoint> nearestIntersection(const PlaneCurve& a,
                                              const PlaneCurve& b,
                                              PlanePoint corner) {
  std::optional<PlanePoint> best;
  for (const PlanePoint point : intersections(a, b)) {
    if (!best || length(point - corner) < length(*best - corner)) {
      best = point;
    }
  }
  return best;
}

/// How the tool gets round the corner between `held` and `next`: the points
/// it passes after the end of `held`. points[0] ends the held move's own
/// path (on its offset circle when it is an arc); the others are joined by
/// straight lines, and the last lies on the next move's offset path.
struct Corner {
  std::vector<PlanePoint> points;
  bool noSolution = false; // PS0033: the offset paths do not meet
};

/// `next.offset`/`next.side` do not count here: the corner takes the vector
/// of the held move's block (a new D acts at the end of its own block).
Corner cornerBetween(const mbrt_ctx& ctx, const HeldMove& held,
                     const HeldMove& next, bool cancel) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint corner = pointOf(held.end, plane);
  const PlanePoint d1 = tangentAt(held, plane, corner);
  const PlanePoint d2 = tangentAt(next, plane, corner);
  const PlanePoint e1 = corner + vectorAt(held, d1);
  const PlanePoint s2 = corner + vectorAt(held, d2);
  const double turn = cross(d1, d2);
  const double along = dot(d1, d2);
  Corner result;
  auto& points = result.points;
  // A straight or tangent continuation: one vector, no corner.
  if (std::fabs(turn) <= 1e-9 && along > 0.0) {
    points = {e1};
    return result;
  }
  const bool typeB = ctx.profile.parameterBit(5003, 0);
  const bool inner = turn * held.side > 0.0;
  if (inner) {
    const std::optional<PlanePoint> meet = nearestIntersection(
        offsetCurve(held, plane, held), offsetCurve(next, plane, held), corner);
    if (!meet) {
      result.noSolution = true;
      return result;
    }
    points = {*meet};
    return result;
  }
  // Outer corners. Type A (start-up and cancel): one vector,
  // perpendicular to the next move at the start, to the last at the end.
  if (!typeB && held.startUp) {
    points = {s2};
    return result;
  }
  if (!typeB && cancel) {
    points = {e1};
    return result;
  }
  // A straight move runs on to the first point below (its end vector lies
  // on the way there); an arc ends at its vector first.
  if (held.arc) {
    points.push_back(e1);
  }
  if (along >= 0.0) {
    PlaneCurve first;
    first.point = e1;
    first.direction = d1;
    PlaneCurve second;
    second.point = s2;
    second.direction = d2;
    const std::vector<PlanePoint> meet = intersections(first, second);
    points.push_back(meet.empty() ? e1 : meet.front());
  } else {
    points.push_back(e1 + held.offset * d1);
    points.push_back(s2 - held.offset * d2);
  }
  if (next.arc && !cancel) {
    points.push_back(s2);
  }
  return result;
}

/// G41 to G42 or back: the intersection of the two offset paths when they
/// cross, else straight from the end vector of one to the start vector of
/// the other.
Corner sideChange(const mbrt_ctx& ctx, const HeldMove& held,
                  const HeldMove& next) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint corner = pointOf(held.end, plane);
  const PlanePoint e1 = corner + vectorAt(held, tangentAt(held, plane, corner));
  const PlanePoint d2 = tangentAt(next, plane, corner);
  const PlanePoint s2 = corner + vectorAt(held.offset, next.side, d2);
  if (!held.arc && !next.arc) {
    const PlanePoint from = pointOf(toolPosition(ctx), plane);
    const PlanePoint to =
        pointOf(next.end, plane) + vectorAt(held.offset, next.side, d2);
    const double det = cross(e1 - from, to - s2);
    if (std::fabs(det) > 1e-9) {
      const double t = cross(s2 - from, to - s2) / det;
      const double u = cross(s2 - from, e1 - from) / det;
      if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0) {
        Corner crossing;
        crossing.points = {from + t * (e1 - from)};
        return crossing;
      }
    }
  }
  Corner apart;
  apart.points = {e1, s2};
  return apart;
}

/// FANUC's interference check (5008#3 CNV = 0) before a move leaves: a
/// straight tool path that runs against its programmed direction (90 to
/// 270 degrees; not with 5008#1 CNC), an arc whose tool path sweeps more
/// than 180 degrees more or less than the programmed one.
bool interferes(const mbrt_ctx& ctx, const HeldMove& move, PlanePoint from,
                PlanePoint to) {
  if (move.startUp || ctx.profile.parameterBit(5008, 3)) {
    return false;
  }
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint start = pointOf(move.start, plane);
  const PlanePoint end = pointOf(move.end, plane);
  if (length(to - from) < 1.0) {
    return false; // nothing left to run against
  }
  if (!move.arc) {
    return !ctx.profile.parameterBit(5008, 1) &&
           dot(end - start, to - from) < 0.0;
  }
  const PlanePoint center = centerOf(move);
  const double programmed = sweepBetween(start, end, center, move.clockwise);
  const double tool = sweepBetween(from, to, center, move.clockwise);
  return std::fabs(tool - programmed) > std::numbers::pi;
}

BlockPlace placeOf(const HeldMove& move) {
  return {move.origin.file, move.origin.line};
}

MoveOrigin originOf(const HeldMove& move) {
  MoveOrigin origin = move.origin;
  origin.program = move.program.c_str();
  origin.programmed = &move.end;
  return origin;
}

/// A move without motion in the plane: the tool keeps its vector.
mbrt_status moveStill(mbrt_ctx& ctx, const HeldMove& move) {
  const PlaneIndex plane = planeIndex(ctx);
  const AxisCounts target =
      placeAt(move, plane, pointOf(toolPosition(ctx), plane));
  if (target == toolPosition(ctx)) {
    return 0;
  }
  return moveWorkStraight(ctx, target, move.rapid, originOf(move));
}

/// The tool centre at the end of a move on a vector perpendicular to it.
PlanePoint perpendicularEnd(const mbrt_ctx& ctx, const HeldMove& move) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint end = pointOf(move.end, plane);
  return end + vectorAt(move, tangentAt(move, plane, end));
}

/// A move as programmed, without offset.
mbrt_status moveAsProgrammed(mbrt_ctx& ctx, const HeldMove& move) {
  if (move.arc) {
    return moveWorkArc(ctx, move.end, centerOf(move), move.clockwise,
                       originOf(move));
  }
  return moveWorkStraight(ctx, move.end, move.rapid, originOf(move));
}

/// The held move leaves along `points` (Corner), then the moves without
/// plane motion read after it; PS0041 instead when its tool path
/// interferes (`check`), the tool standing at the end of the move before.
mbrt_status leave(mbrt_ctx& ctx, const std::vector<PlanePoint>& points,
                  bool check = true) {
  CompensationState& state = *ctx.compensation;
  // Swapped, not moved: both vectors keep their storage from move to move.
  std::vector<HeldMove>& held = state.leaving;
  held.clear();
  held.swap(state.held);
  state.stillBlocks = 0;
  const HeldMove& move = held.front();
  // The control had placed the move before later blocks changed offsets
  // (16/18-MC manual: a new offset acts from the block that gives it).
  const PlacedAs placed(ctx, move.placement);
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint from = pointOf(toolPosition(ctx), plane);
  if (check && interferes(ctx, move, from, points.front())) {
    if (ctx.profile.parameterBit(19607, 5)) {
      return raiseAt(ctx, placeOf(move), AlarmId::Unsupported,
                     "interference avoidance (parameter 19607#5 CAV)");
    }
    return raiseAt(ctx, placeOf(move), AlarmId::InterferenceInCrc,
                   fmt::format("the tool path of this {} runs against the "
                               "programmed direction with offset {}",
                               move.arc ? "arc" : "move",
                               move.offset / ctx.scale()));
  }
  const MoveOrigin origin = originOf(move);
  const AxisCounts first = placeAt(move, plane, points.front());
  const bool fullCircle =
      move.arc && pointOf(move.start, plane).x == pointOf(move.end, plane).x &&
      pointOf(move.start, plane).y == pointOf(move.end, plane).y;
  mbrt_status status = 0;
  if (move.arc) {
    if (first != toolPosition(ctx) || fullCircle) {
      status = moveWorkArc(ctx, first, centerOf(move), move.clockwise, origin);
    }
  } else if (first != toolPosition(ctx)) {
    status = moveWorkStraight(ctx, first, move.rapid, origin);
  }
  for (std::size_t i = 1; i < points.size() && status == 0; ++i) {
    const AxisCounts link = placeAt(move, plane, points[i]);
    if (link != toolPosition(ctx)) {
      status = moveWorkStraight(ctx, link, move.rapid, origin);
    }
  }
  for (std::size_t i = 1; i < held.size() && status == 0; ++i) {
    const PlacedAs stillPlaced(ctx, held[i].placement);
    status = moveStill(ctx, held[i]);
  }
  return status;
}

/// The offset value of the modal D (geometry + wear as the offset memory
/// keeps it) in counts, and the side: G41 left, G42 right, swapped by a
/// negative value and by a mirror image in the plane.
mbrt_status readOffset(mbrt_ctx& ctx, HeldMove& move) {
  if (ctx.profile.lathe()) { // the nose radius of the T code's offset
    move.offset = static_cast<double>(noseTool(ctx).radius);
    move.side = ctx.machine.modal.compensation == 41 ? 1 : -1;
    return 0;
  }
  const double d = ctx.machine.lastWords[lastWordSlot(LastWord::D)];
  if (d < 0.0 || d > ctx.profile.toolOffsetCount) {
    return raise(ctx, AlarmId::IllegalOffsetNumber,
                 fmt::format("D{} (the machine has {})", d,
                             ctx.profile.toolOffsetCount));
  }
  const ToolOffset& offset = ctx.data.toolOffsets[static_cast<std::size_t>(d)];
  double value = 0.0;
  switch (ctx.profile.toolOffsetMemory) {
    case 'A':
      value = offset.hGeometry;
      break;
    case 'B':
      value = offset.hGeometry + offset.hWear;
      break;
    default:
      value = offset.dGeometry + offset.dWear;
      break;
  }
  const PlaneIndex plane = planeIndex(ctx);
  const bool mirrored = arcFrame(ctx, plane.p, plane.q).reversed;
  move.offset = roundToLengthCounts(ctx, std::fabs(value));
  move.side = (ctx.machine.modal.compensation == 41) == (value >= 0.0) ? 1 : -1;
  if (mirrored) {
    move.side = -move.side;
  }
  return 0;
}

/// A lathe's tool nose radius compensation: the imaginary tip, not the
/// nose centre, is the control point, and offsetting commutes with moving
/// the path, so the offset path of the programmed one moved by the tip
/// vector is the tip's path. The vectors come from the programmed path, so
/// every move under compensation moves whole; the cancel move still ends
/// with the tip on its programmed end (cancel), and the start-up starts
/// where the tool is.
void followTip(const mbrt_ctx& ctx, HeldMove& move);

/// G41 or G42 with an offset number other than D0.
bool offsetOn(const mbrt_ctx& ctx) {
  return ctx.machine.modal.compensation != 40 &&
         (ctx.profile.lathe() ||
          ctx.machine.lastWords[lastWordSlot(LastWord::D)] != 0.0);
}

void followTip(const mbrt_ctx& ctx, HeldMove& move) {
  if (!ctx.compensation->engaged && !offsetOn(ctx)) {
    return;
  }
  move.tipShift = noseTool(ctx).tip;
  const PlaneIndex plane = planeIndex(ctx);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    move.start[axis] += move.tipShift[axis];
    move.end[axis] += move.tipShift[axis];
  }
  move.center[0] += static_cast<double>(move.tipShift[plane.p]);
  move.center[1] += static_cast<double>(move.tipShift[plane.q]);
}

/// The blocks without plane motion the look-ahead tolerates between two
/// moves: 19625 less two (a value outside 3 to 8 reads as 3).
int stillBlocksAllowed(const mbrt_ctx& ctx) {
  const double blocks = ctx.profile.parameter(19625);
  return (blocks >= 3.0 && blocks <= 8.0 ? static_cast<int>(blocks) : 3) - 2;
}

/// The offset path of a virtual line through `corner` along the I J K
/// direction `along` carries, at the side and offset of `by`.
PlaneCurve virtualPath(PlanePoint corner, const HeldMove& along,
                       const HeldMove& by) {
  PlaneCurve path;
  path.direction = unit({along.direction[0], along.direction[1]});
  path.point = corner + vectorAt(by, path.direction);
  return path;
}

/// G40 with I J K: the held move ends where its offset path meets that of
/// a virtual path from its end along I J, inner corner or outer, or on its
/// perpendicular vector where they do not meet.
PlanePoint towardDirection(const mbrt_ctx& ctx, const HeldMove& held,
                           const HeldMove& cancel) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint corner = pointOf(held.end, plane);
  const std::optional<PlanePoint> meet =
      nearestIntersection(offsetCurve(held, plane, held),
                          virtualPath(corner, cancel, held), corner);
  return meet ? *meet : perpendicularEnd(ctx, held);
}

/// G41/G42 X Y I J at the start-up: the start-up move ends where the
/// offset of a virtual path along I J into its end meets the next move's
/// offset path, inner corner or outer, or on the next move's perpendicular
/// vector where they do not meet.
PlanePoint startAlongDirection(const mbrt_ctx& ctx, const HeldMove& startUp,
                               const HeldMove& next) {
  const PlaneIndex plane = planeIndex(ctx);
  const PlanePoint corner = pointOf(startUp.end, plane);
  const std::optional<PlanePoint> meet =
      nearestIntersection(virtualPath(corner, startUp, startUp),
                          offsetCurve(next, plane, startUp), corner);
  return meet ? *meet
              : corner + vectorAt(startUp, tangentAt(next, plane, corner));
}

/// Parameter 5003#2 CCN = 1 restores the vector after G28, G29, G30 and G53
/// as the FS15 does (an intersection vector), which mbc does not model.
mbrt_status refuseFs15Restoration(mbrt_ctx& ctx) {
  if (!ctx.profile.parameterBit(5003, 2)) {
    return 0;
  }
  return raise(ctx, AlarmId::Unsupported,
               "G28, G29, G30 or G53 in cutter compensation mode with "
               "5003#2 CCN (the FS15 vector after them)");
}

/// The cancel move: from where the tool is straight to the programmed end.
mbrt_status cancel(mbrt_ctx& ctx, HeldMove& move) {
  CompensationState& state = *ctx.compensation;
  if (move.arc) {
    return raise(ctx, AlarmId::NoCircleAtStartOrCancel,
                 "the move that cancels cutter compensation must be G00 or "
                 "G01");
  }
  if (!state.held.empty() && move.hasDirection) {
    if (const mbrt_status status =
            leave(ctx, {towardDirection(ctx, state.held.front(), move)})) {
      return status;
    }
  } else if (!state.held.empty()) {
    const Corner corner = cornerBetween(ctx, state.held.front(), move, true);
    if (corner.noSolution) {
      state.held.clear();
      return raise(ctx, AlarmId::NoSolutionAtCrc,
                   "the offset paths do not meet at the cancel move");
    }
    if (const mbrt_status status = leave(ctx, corner.points)) {
      return status;
    }
  }
  state.engaged = false;
  AxisCounts end = move.end; // a lathe's tip back on the programmed end
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    end[axis] -= move.tipShift[axis];
  }
  return moveWorkStraight(ctx, end, move.rapid, originOf(move));
}

} // namespace

mbrt_status compensateMove(mbrt_ctx& ctx, HeldMove move) {
  CompensationState& state = *ctx.compensation;
  const PlaneIndex plane = planeIndex(ctx);
  if (plane.p < 0 || plane.q < 0) {
    const PlaneAxes axes = planeAxes(ctx.machine.modal.plane);
    return raise(ctx, AlarmId::IllegalPlaneSelect,
                 fmt::format("cutter compensation in G{} needs axes {} and {}",
                             ctx.machine.modal.plane, axes.letters[0],
                             axes.letters[1]));
  }
  if (ctx.profile.lathe()) {
    followTip(ctx, move);
  }
  move.origin = blockOrigin(ctx);
  move.program = move.origin.program;
  move.placement = placementOf(ctx);
  move.still = !move.arc &&
               pointOf(move.start, plane).x == pointOf(move.end, plane).x &&
               pointOf(move.start, plane).y == pointOf(move.end, plane).y;
  if (move.still) {
    if (state.held.empty()) {
      return moveStill(ctx, move);
    }
    state.held.push_back(std::move(move));
    return 0;
  }
  ++state.planeMoves;
  if (!offsetOn(ctx)) {
    if (!state.engaged) {
      return moveAsProgrammed(ctx, move);
    }
    return cancel(ctx, move);
  }
  if (const mbrt_status status = readOffset(ctx, move)) {
    return status;
  }
  if (!state.engaged && move.arc) {
    return raise(ctx, AlarmId::NoCircleAtStartOrCancel,
                 "the move that starts cutter compensation must be G00 or "
                 "G01");
  }
  // An inside arc no larger than the offset: on the arc's centre the
  // control stops with PS0038, inside out with PS0041.
  const double toolRadius = move.arc ? offsetRadius(move, plane, move) : 0.0;
  if (move.arc && toolRadius < 0.5) {
    // The tool stops at the end of the move before, which has no corner.
    if (const mbrt_status status = releaseHeldMoves(ctx)) {
      return status;
    }
    const double radius =
        length(pointOf(move.start, plane) - centerOf(move)) / ctx.scale();
    return toolRadius > -0.5
               ? raise(ctx, AlarmId::InterferenceInCircle,
                       fmt::format("the tool centre would stand on the "
                                   "arc's centre: radius {} = offset {}",
                                   radius, move.offset / ctx.scale()))
               : raise(ctx, AlarmId::InterferenceInCrc,
                       fmt::format("the arc's radius {} is smaller than "
                                   "the offset {} on its inside",
                                   radius, move.offset / ctx.scale()));
  }
  if (!state.engaged) {
    // Parameters that would change the path mbc draws: stop, never guess.
    if (ctx.profile.parameterBit(5003, 1) ||
        ctx.profile.parameterBit(19607, 2)) {
      return raise(ctx, AlarmId::Unsupported,
                   ctx.profile.parameterBit(5003, 1)
                       ? "cutter compensation with 5003#1 SUV (the vector of "
                         "a start-up or cancel without motion)"
                       : "cutter compensation with 19607#2 CCC (circular "
                         "connection of outer corners)");
    }
    move.startUp = true;
    state.engaged = true;
    state.held.push_back(std::move(move));
    state.stillBlocks = 0;
    return 0;
  }
  if (!state.held.empty()) {
    const HeldMove& held = state.held.front();
    Corner corner;
    if (held.side != move.side && !held.startUp) {
      corner = sideChange(ctx, held, move);
    } else if (held.startUp && held.hasDirection) {
      corner.points = {startAlongDirection(ctx, held, move)};
    } else if (state.codeInBlock && !held.startUp) {
      // G41/G42 given again: the vector at the end of the move before is
      // perpendicular to it, inner corner or outer.
      corner.points = {perpendicularEnd(ctx, held)};
    } else {
      corner = cornerBetween(ctx, held, move, false);
    }
    if (corner.noSolution) {
      const HeldMove failed = held;
      state.held.clear();
      return raiseAt(ctx, placeOf(failed), AlarmId::NoSolutionAtCrc,
                     "the offset paths of this move and the next do not "
                     "meet");
    }
    if (const mbrt_status status = leave(ctx, corner.points)) {
      return status;
    }
  }
  state.held.push_back(std::move(move));
  return 0;
}

mbrt_status cancelCompensation(mbrt_ctx& ctx, HeldMove move) {
  if (const mbrt_status status = refuseFs15Restoration(ctx)) {
    return status;
  }
  const PlaneIndex plane = planeIndex(ctx);
  move.origin = blockOrigin(ctx);
  move.program = move.origin.program;
  const PlanePoint start = pointOf(move.start, plane);
  const PlanePoint end = pointOf(move.end, plane);
  if (start.x != end.x || start.y != end.y) {
    ++ctx.compensation->planeMoves;
    return cancel(ctx, move);
  }
  // Other axes alone: the plane's axes stay on the vector the move before
  // ends with, as under G53.
  if (const mbrt_status status = releaseHeldMoves(ctx)) {
    return status;
  }
  return moveStill(ctx, move);
}

mbrt_status suspendCompensation(mbrt_ctx& ctx, std::uint32_t mask) {
  if (!ctx.compensation->engaged || mask == 0) {
    return 0;
  }
  if (const mbrt_status status = refuseFs15Restoration(ctx)) {
    return status;
  }
  const PlaneIndex plane = planeIndex(ctx);
  const unsigned planeAxes = (mask >> plane.p & 1U) + (mask >> plane.q & 1U);
  if (planeAxes == 1) {
    // The manual shows the plane's two axes, or neither.
    return raise(ctx, AlarmId::Unsupported,
                 "G53 with one axis of the compensation plane in cutter "
                 "compensation mode (G41/G42); give both, or give it after "
                 "G40");
  }
  if (const mbrt_status status = releaseHeldMoves(ctx)) {
    return status;
  }
  ctx.compensation->engaged = planeAxes == 0;
  return 0;
}

mbrt_status releaseHeldMoves(mbrt_ctx& ctx, bool check) {
  CompensationState& state = *ctx.compensation;
  if (state.held.empty()) {
    return 0;
  }
  return leave(ctx, {perpendicularEnd(ctx, state.held.front())}, check);
}

mbrt_status cancelVectorHere(mbrt_ctx& ctx) {
  CompensationState& state = *ctx.compensation;
  if (!state.engaged) {
    return 0;
  }
  const PlaneIndex plane = planeIndex(ctx);
  const AxisCounts here = programToWork(ctx, ctx.machine.program);
  if (!state.held.empty()) {
    if (const mbrt_status status = leave(ctx, {pointOf(here, plane)})) {
      return status;
    }
  } else if (here != toolPosition(ctx)) {
    if (const mbrt_status status = moveWorkStraight(
            ctx, here, ctx.machine.modal.motion == 0, blockOrigin(ctx))) {
      return status;
    }
  }
  state.engaged = false;
  return 0;
}

mbrt_status stopLookAhead(mbrt_ctx& ctx) {
  if (ctx.compensation->held.empty()) {
    return 0;
  }
  flattenLookAheadStop(ctx, stillBlocksAllowed(ctx) + 1);
  return releaseHeldMoves(ctx);
}

mbrt_status compensateBlockEnd(mbrt_ctx& ctx, std::uint64_t planeMovesBefore) {
  CompensationState& state = *ctx.compensation;
  if (state.planeMoves != planeMovesBefore || !state.engaged) {
    return 0;
  }
  if (ctx.corner->pending && ctx.corner->fresh) {
    return 0; // a move in the plane, held for its chamfer or corner R
  }
  // G40 alone: the vector goes with the next move in the plane. G41/G42
  // alone: the vector at the end of the move before is perpendicular.
  if (!offsetOn(ctx) || state.codeInBlock) {
    return releaseHeldMoves(ctx);
  }
  if (!state.held.empty() && ++state.stillBlocks > stillBlocksAllowed(ctx)) {
    return releaseHeldMoves(ctx);
  }
  return 0;
}

mbrt_status cornerArc(mbrt_ctx& ctx, const MotionWords& words) {
  CompensationState& state = *ctx.compensation;
  if (!state.engaged || !offsetOn(ctx)) {
    return raise(ctx, AlarmId::ImproperGCode,
                 "G39 corner arc outside cutter compensation (G41/G42)");
  }
  const PlaneIndex plane = planeIndex(ctx);
  // The direction in program coordinates, then through the frames.
  PlanePoint programmed = centerWords(ctx, words);
  if (words.centerMask == 0) {
    const PlanePoint from = pointOf(ctx.machine.program, plane);
    PlanePoint toward = from;
    if ((words.axisMask >> plane.p & 1) != 0) {
      toward.x = static_cast<double>(words.axis[plane.p]) +
                 (ctx.machine.modal.incremental ? from.x : 0.0);
    }
    if ((words.axisMask >> plane.q & 1) != 0) {
      toward.y = static_cast<double>(words.axis[plane.q]) +
                 (ctx.machine.modal.incremental ? from.y : 0.0);
    }
    programmed = toward - from;
  }
  const AxisCounts here = programToWork(ctx, ctx.machine.program);
  const PlanePoint direction = unit(workDirection(ctx, programmed));
  if (length(direction) == 0.0) {
    return raise(ctx, AlarmId::ImproperCommand,
                 "G39 needs a direction: X Y or I J away from the corner");
  }
  ++state.planeMoves;
  HeldMove arc;
  arc.end = here;
  if (const mbrt_status status = readOffset(ctx, arc)) {
    return status;
  }
  if (!state.held.empty()) {
    // The manuals draw G39 at outer corners only; at an inner one its arc
    // would turn 270 degrees about the corner, through the far side.
    const HeldMove& held = state.held.front();
    const PlanePoint end = tangentAt(held, plane, pointOf(held.end, plane));
    if (cross(end, direction) * arc.side > 1e-9) {
      return raise(ctx, AlarmId::Unsupported,
                   "G39 at an inner corner (its arc would turn 270 degrees "
                   "about the corner, through the far side)");
    }
  }
  if (const mbrt_status status = releaseHeldMoves(ctx)) {
    return status;
  }
  const PlanePoint corner = pointOf(here, plane);
  const AxisCounts target =
      placeAt(arc, plane, corner + vectorAt(arc, direction));
  AxisCounts tool = toolPosition(ctx);
  for (const int axis : {plane.p, plane.q}) {
    tool[axis] = target[axis];
  }
  if (tool != toolPosition(ctx)) {
    MoveOrigin origin = blockOrigin(ctx);
    origin.programmed = &here;
    return moveWorkArc(ctx, tool, corner, arc.side > 0, origin);
  }
  return 0;
}

void readVectorDirection(const mbrt_ctx& ctx, const MotionWords& words,
                         HeldMove& move) {
  const PlaneIndex plane = planeIndex(ctx);
  if (plane.p >= 0 && plane.q >= 0) {
    const PlanePoint direction = workDirection(ctx, centerWords(ctx, words));
    move.hasDirection = true;
    move.direction[0] = direction.x;
    move.direction[1] = direction.y;
  }
}

} // namespace mbc::rt
