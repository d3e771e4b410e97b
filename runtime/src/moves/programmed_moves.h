// The moves a program commands (G00-G03, G28-G31, G53), from the program
// position to a target in program coordinates: through cutter
// compensation when it is on (cutter_comp.h), else straight to the tool
// moves (tool_moves.h). Cycles and corners hand their moves on here.
#pragma once

#include <optional>

#include "context.h"
#include "motion_words.h"
#include "plane_geometry.h"

namespace mbc::rt {

/// The end point of a block's axis words from `start` (program
/// coordinates): G90/G91, a lathe's incremental addresses, and the shorter
/// way on an axis that rolls over.
AxisCounts workTarget(const mbrt_ctx& ctx, const MotionWords& words,
                      const AxisCounts& start);

/// A G02 or G03 arc of the block's words from `start` to `target` (program
/// coordinates) in the modal motion mode, through cutter compensation when
/// it is on (PS0011 without F).
mbrt_status moveArc(mbrt_ctx& ctx, const MotionWords& words,
                    const AxisCounts& start, const AxisCounts& target);

/// A straight move to `target` (program coordinates): a rapid, or a feed
/// at the modal F (PS0011 when F is 0). `cycle` marks a canned cycle's move.
mbrt_status moveStraight(mbrt_ctx& ctx, const AxisCounts& target, bool rapid,
                         int cycle = 0);

/// An arc from the program position to `end` about `center` (program
/// coordinates, the plane's axes), as a G02 (`clockwise`) or G03 of the
/// program would run it, through cutter compensation when it is on.
mbrt_status moveArcAbout(mbrt_ctx& ctx, const AxisCounts& end,
                         const AxisCounts& center, bool clockwise);

/// The centre (the plane's axes, program counts) of the arc that a G02
/// (`clockwise`) or G03 block's R or I, J, K give from `start` to
/// `target`; none without them. The plane must have both axes.
std::optional<PlanePoint> arcCenter(const mbrt_ctx& ctx,
                                    const MotionWords& words,
                                    const AxisCounts& start,
                                    const AxisCounts& target, bool clockwise);

/// PS0020 when a G02/G03 block's R falls short of half the distance from
/// `start` to `target` by more than parameter 3410: no arc of that radius
/// reaches the end point. Within the tolerance the arc is the semicircle,
/// as rounded end points need.
mbrt_status checkRadiusReaches(mbrt_ctx& ctx, const MotionWords& words,
                               const AxisCounts& start,
                               const AxisCounts& target);

/// A G00 or G01 move of the program to `target` (program coordinates),
/// which cutter compensation may hold; `words` give G41/G42 I J K.
mbrt_status moveLine(mbrt_ctx& ctx, const AxisCounts& target, bool rapid,
                     const MotionWords* words = nullptr);

/// After the tool length offset changed in a block without motion: the
/// control point moves so that the program position stays (G43 H1 alone
/// moves Z by the offset), a rapid in G00 and a feed otherwise.
mbrt_status moveToFrame(mbrt_ctx& ctx);

/// G28 (`reference` 1) and G30 P2-P4: rapid to the intermediate point the
/// axis words give, then the control point to the reference position on
/// those axes: machine zero, or parameter 1241-1243. G29 remembers the
/// intermediate point.
mbrt_status returnToReference(mbrt_ctx& ctx, const MotionWords& words,
                              int reference);

/// G29: rapid through the last G28/G30 intermediate point to the point the
/// axis words give.
mbrt_status returnFromReference(mbrt_ctx& ctx, const MotionWords& words);

/// G31 (P1) to G31 P4: a feed move that stops where the probe first touches
/// a solid of the profile's scene that gives that skip signal, or completes
/// without contact; #5061 takes where it ended.
mbrt_status skipMove(mbrt_ctx& ctx, const MotionWords& words, double p);

/// G53: rapid to machine coordinates on the axes written (ignored in G91).
mbrt_status moveInMachineCoordinates(mbrt_ctx& ctx, const MotionWords& words);

} // namespace mbc::rt
