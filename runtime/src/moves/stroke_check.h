// The stored stroke check 1 (parameters 1320/1321): a move of the control
// point that would take an axis past an end of its stroke, in machine
// coordinates, alarms at its block (OT0500 past the + end, OT0501 past the
// - end) before it moves: the toolpath ends where that block started
// (docs/language.md, "Stroke limits").
#pragma once

#include "context.h"
#include "move_state.h"

namespace mbc::rt {

/// Whether moves are checked: some axis has a stroke, and the moves are the
/// tool's, not those of a lathe's shape being read or found.
inline bool checksStroke(const mbrt_ctx& ctx) {
  return ctx.profile.strokeAxes() != 0 && !ctx.run.readingShape() &&
         !ctx.run.dryRun;
}

/// A straight move from where the control point stands to `machine`.
mbrt_status checkLineStroke(mbrt_ctx& ctx, const AxisCounts& machine,
                            const MoveOrigin& origin);

/// An arc to `machine` (workpiece position `work`): its plane axes as far
/// as the arc takes them, the others straight.
mbrt_status checkArcStroke(mbrt_ctx& ctx, const AxisCounts& work,
                           const AxisCounts& machine, const ArcPath& arc,
                           const MoveOrigin& origin);

} // namespace mbc::rt
