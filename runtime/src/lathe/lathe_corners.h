// Chamfering and corner R of a lathe (30i/0i manual, "Chamfering and
// corner R"): a G01 along one axis of the plane with I, J or K (C when
// parameter 3405#4 CCR is 1) ends with a 45 degree chamfer, or with R a
// quarter arc, into the next G01, which runs along the other axis. In
// G18, `G01 Z_ I±i` chamfers into X (i a radius), `G01 X_ K±k` into Z;
// `G01 Z_ R±r` and `G01 X_ R±r` round the corner; the sign is the
// direction of the next move. The tool goes from a to d (the amount short
// of the corner b), then to c (the amount along the next move), and the
// next block's incremental words count from b.
#pragma once

#include "context.h"
#include "held_block.h"
#include "motion_words.h"
#include "programmed_moves.h"

namespace mbc::rt {

/// Whether C is the chamfer address: a lathe with 3405#4 CCR and no C axis.
bool chamferByC(const mbrt_ctx& ctx);

/// Whether A is the angle of direct drawing dimensions (,A): a lathe with
/// 3405#4 CCR and no A axis.
bool angleByA(const mbrt_ctx& ctx);

/// Whether a lathe's G01 block's words ask for a chamfer or a corner R.
bool insertsCorner(const mbrt_ctx& ctx, const MotionWords& words);

/// The G01 block with the chamfer or corner R: checks it and holds its
/// move from `start` to `target` (program coordinates) for the next block.
mbrt_status holdCornerMove(mbrt_ctx& ctx, const MotionWords& words,
                           const AxisCounts& start, const AxisCounts& target);

/// The next block's move to `target`: the held move up to d, the chamfer
/// or arc to c, then this move from c (held in turn when its `words` ask
/// for a corner); PS0051, PS0052 or PS0055 when the move cannot take the
/// corner.
mbrt_status moveAfterCorner(mbrt_ctx& ctx, const MotionWords& words,
                            const AxisCounts& target);

/// At the end of an NC block while a move is held: a block after the
/// held one that did not take the corner is PS0051.
mbrt_status checkCornerTaken(mbrt_ctx& ctx);

/// The run ends with a move still held: it goes as programmed.
void releaseCornerMove(mbrt_ctx& ctx);

} // namespace mbc::rt
