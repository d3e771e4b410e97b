// How fast a lathe's spindle turns along a move, for the simulated clock of
// feeds per revolution and threads: S rpm in G97; in G96 (constant surface
// speed) the speed S m/min (ft/min in G20) gives at the programmed point's
// distance from the spindle axis (X), capped by G50 S and parameter 3772.
#pragma once

#include "context.h"
#include "move_state.h"
#include "plane_geometry.h"

namespace mbc::rt {

/// Minutes per spindle revolution in G96, averaged over a straight move
/// from the control point's workpiece position to `to` (counts); 0 outside
/// G96, where the speed is S throughout. The position is found only in
/// G96: every feed move of a mill asks.
double lineTurnMinutes(const mbrt_ctx& ctx, const MoveOrigin& origin,
                       const AxisCounts& to);

/// The same over an arc (`start`: the control point's workpiece position).
double arcTurnMinutes(const mbrt_ctx& ctx, const MoveOrigin& origin,
                      const ArcPath& arc, const AxisCounts& start);

} // namespace mbc::rt
