// Chamfering and corner R at any angle, and the angle of a line (30i/0i
// manuals, "Chamfering and corner R" and, on lathes, "Direct drawing
// dimension programming"). `,C c` at the end of a G01, G02 or G03 block
// cuts the corner with the next block's move by a straight line from the
// point c short of the corner to the point c past it (straight distances
// from the corner, on lines and arcs alike); `,R r` rounds it with an arc
// of radius r tangent to both moves. The block's move is held until the
// next block tells where it goes, as lathe_corners.h holds its 90 degree
// forms, and the inserted move runs as the held block (its F and line).
//
// `,A a` gives the direction of a G00 or G01 line, in degrees from the
// plane's first axis, counter-clockwise: with one of the plane's two
// coordinates the other follows; with neither, the next block's end point
// and its own ,A make the corner where the two lines meet.
#pragma once

#include "context.h"
#include "motion_words.h"
#include "programmed_moves.h"

namespace mbc::rt {

/// PS0021 for a corner or ,A line in a plane the machine lacks an axis of.
mbrt_status missingPlaneAxis(mbrt_ctx& ctx);

/// Whether a block's words hold ,C ,R or ,A.
inline bool hasCommaWords(const MotionWords& words) {
  return words.blend != 0 || words.angle.has_value();
}

/// Whether the block's move waits for the next block: it ends with ,C or
/// ,R, or it is a ,A line without an end point.
bool holdsForNextBlock(const mbrt_ctx& ctx, const MotionWords& words);

/// ,A of a G00 or G01 block that gives one coordinate of the plane: the
/// other one of `target`, on the line from `start`. Nothing to do when the
/// block gives neither (the corner comes with the next block). PS0053 when
/// it gives both or moves in G02/G03; PS0057 when the line never reaches
/// the coordinate.
mbrt_status endAngledLine(mbrt_ctx& ctx, const MotionWords& words,
                          const AxisCounts& start, AxisCounts& target);

/// A block with ,C ,R or a ,A line without end point, and no held move:
/// checks it and holds its move from `start` to `target`.
mbrt_status holdBlendMove(mbrt_ctx& ctx, const MotionWords& words,
                          const AxisCounts& start, const AxisCounts& target);

/// The next block's move to `target` after a held ,C ,R or open ,A: the
/// held move to where the chamfer or arc starts, the chamfer or arc, then
/// this block's move (held in turn when its words ask for a corner).
/// PS0052 when this block is no G01, G02 or G03, PS0055 when a move is
/// shorter than the corner takes, PS0056 to PS0058 when an open ,A gets
/// no corner.
mbrt_status moveAfterBlend(mbrt_ctx& ctx, const MotionWords& words,
                           const AxisCounts& target);

/// The held move as programmed (the run ended after it).
mbrt_status runHeldAsProgrammed(mbrt_ctx& ctx, const CornerInsertion& held);

} // namespace mbc::rt
