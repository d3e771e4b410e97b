// The last stage of motion: the control point's moves in the workpiece
// frame, as the stages above them (programmed_moves.h, cutter_comp.h) hand
// them on, with the simulated #3001/#3002 clock, the toolpath's box and the
// motion sink. Nothing here calls a stage above.
#pragma once

#include "context.h"
#include "move_state.h"
#include "plane_geometry.h"

namespace mbc::rt {

/// The block data a move carries, taken now: the current block, feed and
/// spindle speed; `cycle` names the canned cycle it belongs to.
MoveOrigin blockOrigin(const mbrt_ctx& ctx, int cycle = 0);

/// The two axes of a plane (G17 X Y, G18 Z X, G19 Y Z) and the I/J/K index
/// of each.
struct PlaneAxes {
  char letters[2];
  int centerIndex[2];
};

/// Inline: every arc and every move in a plane asks.
inline PlaneAxes planeAxes(int plane) {
  switch (plane) {
    case 18:
      return {{'Z', 'X'}, {2, 0}};
    case 19:
      return {{'Y', 'Z'}, {1, 2}};
    default:
      return {{'X', 'Y'}, {0, 1}};
  }
}

/// The current plane's two axes as indexes into positions (-1 where the
/// machine lacks one).
struct PlaneIndex {
  int p;
  int q;
};

inline PlaneIndex planeIndex(const mbrt_ctx& ctx) {
  const PlaneAxes plane = planeAxes(ctx.machine.modal.plane);
  return {ctx.axisOf(plane.letters[0]), ctx.axisOf(plane.letters[1])};
}

/// G20/G21: re-expresses the position, the offsets and the frames in the
/// new unit.
void switchUnits(mbrt_ctx& ctx, bool inch);

/// The position of every axis as the program commands it: local
/// coordinates before mirror, scaling and rotation (frames.h).
const AxisCounts& programPosition(const mbrt_ctx& ctx);

/// Cutter compensation's moves (cutter_comp.h): the control point goes
/// straight, or on an arc about `center` (the plane's axes), to a position
/// in the workpiece frame, as the block of `origin` commanded.
///
/// Every move here is checked against the strokes first (stroke_check.h):
/// past one, it alarms at the block of `origin` and does not move.
[[nodiscard]] mbrt_status moveWorkStraight(mbrt_ctx& ctx,
                                           const AxisCounts& work, bool rapid,
                                           const MoveOrigin& origin);
[[nodiscard]] mbrt_status moveWorkArc(mbrt_ctx& ctx, const AxisCounts& work,
                                      PlanePoint center, bool clockwise,
                                      const MoveOrigin& origin);

/// A straight move of the control point to `machine` (workpiece position
/// `work`).
[[nodiscard]] mbrt_status moveStraightTo(mbrt_ctx& ctx, const AxisCounts& work,
                                         const AxisCounts& machine, bool rapid,
                                         const MoveOrigin& origin);

/// An arc of the control point to `work` about `center` (workpiece counts
/// in the plane), `radius` long and turning through `sweep` radians as the
/// program's frame measures them.
[[nodiscard]] mbrt_status moveArcTo(mbrt_ctx& ctx, const AxisCounts& work,
                                    PlanePoint center, double radius,
                                    double sweep, bool clockwise,
                                    const MoveOrigin& origin);

/// Advances the simulated clock by a dwell.
void dwell(mbrt_ctx& ctx, double seconds);

} // namespace mbc::rt
