// Cutter compensation C (G40, G41, G42 and G39; docs/language.md "Cutter
// compensation"): the tool centre runs at the offset value beside the
// programmed path, in the plane of G17/G18/G19, computed in the workpiece
// frame. A move in the plane is held until the next one tells how its end
// meets it (intersection, or the FANUC vectors of an outer corner); the
// blocks without motion in the plane read meanwhile count against the
// look-ahead of parameter 19625, past which the held move ends with a
// vector perpendicular to it, as the control does.
#pragma once

#include <string_view>

#include "context.h"
#include "cutter_comp_state.h"
#include "motion_words.h"

namespace mbc::rt {

/// A programmed move (G00-G03, start and end in the workpiece frame;
/// ctx.machine.program already at its end): the start-up, a move in offset
/// mode, the cancel move, or a move without motion in the plane.
mbrt_status compensateMove(mbrt_ctx& ctx, HeldMove move);

/// The tool leaves the offset on `move` (G28/G30 to the intermediate
/// point) as a cancel move does. A move without motion in the plane ends
/// the held move on its perpendicular vector and keeps the vector.
mbrt_status cancelCompensation(mbrt_ctx& ctx, HeldMove move);

/// G53 positioning the axes in `mask` (0i-MB manual, "G53 ... in cutter
/// compensation C mode"): the move before ends on its perpendicular
/// vector; when the plane's axes move the vector goes with them and the
/// next move in the plane starts it again, otherwise it stays.
mbrt_status suspendCompensation(mbrt_ctx& ctx, std::uint32_t mask);

/// After every NC block under compensation: a block without motion in the
/// plane counts against the look-ahead, and G40 or D0 in such a block ends
/// the held move with a perpendicular vector.
mbrt_status compensateBlockEnd(mbrt_ctx& ctx, std::uint64_t planeMovesBefore);

/// A lathe's cycle starts (0i-TF manual, canned cycles and tool nose
/// radius compensation): the offset vector is cancelled at its start
/// point, the program position. The held move ends there; the cycle's own
/// moves start the offset again, and so does the next move after it.
mbrt_status cancelVectorHere(mbrt_ctx& ctx);

/// G39 corner circular interpolation: an arc of the offset value about the
/// programmed point, to the vector perpendicular to the direction the
/// block's plane words (X Y, or I J) give.
mbrt_status cornerArc(mbrt_ctx& ctx, const MotionWords& words);

/// G40/G41/G42 X Y I J: the direction the plane's I J K give, in the
/// workpiece frame, for the virtual path of the start-up or cancel move.
void readVectorDirection(const mbrt_ctx& ctx, const MotionWords& words,
                         HeldMove& move);

/// The held moves leave, the one in the plane with a vector perpendicular
/// to its end; at the end of the run `check` is false: no interference
/// check, whose alarm would come after the program ended.
mbrt_status releaseHeldMoves(mbrt_ctx& ctx, bool check = true);

/// A read of the tool position (#5021, #5041) stops the look-ahead: the
/// held moves leave, and the flattened program gets as many blocks without
/// motion as stop the control's look-ahead.
mbrt_status stopLookAhead(mbrt_ctx& ctx);

} // namespace mbc::rt
