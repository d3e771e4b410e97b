// The motion of NC blocks: linear and circular geometry, positions in
// machine and workpiece coordinates, the simulated clock and the motion sink.
#pragma once

#include <optional>

#include "context.h"
#include "move_state.h"
#include "plane_geometry.h"

namespace mbc::rt {

/// The words of one block that define its motion, in counts.
struct MotionWords {
  std::uint32_t axisMask = 0; // bit a: axis a was written
  AxisCounts axis{};          // as written (absolute or incremental)
  // Bit a: axis a was written with its incremental address (a lathe's U
  // for X, W for Z), whatever G90/G91 says.
  std::uint32_t incrementalMask = 0;
  std::uint32_t centerMask = 0; // bit 0: I, 1: J, 2: K
  std::array<Counts, 3> center{};
  bool hasR = false;
  Counts r = 0;
  // A lathe's chamfer amount C, when 3405#4 CCR gives C for I and K.
  bool hasC = false;
  Counts c = 0;
  // ,C or ,R (corner_blends.h): 'C' or 'R' and its amount; 0 for none.
  char blend = 0;
  Counts blendAmount = 0;
  // ,A: the angle of the line from the plane's first axis, in degrees.
  std::optional<double> angle;
};

/// The block data a move carries, taken now: the current block, feed and
/// spindle speed; `cycle` names the canned cycle it belongs to.
MoveOrigin blockOrigin(const mbrt_ctx& ctx, int cycle = 0);

/// The two axes of a plane (G17 X Y, G18 Z X, G19 Y Z) and the I/J/K index
/// of each.
struct PlaneAxes {
  char letters[2];
  int centerIndex[2];
};

PlaneAxes planeAxes(int plane);

/// The current plane's two axes as indexes into positions (-1 where the
/// machine lacks one).
struct PlaneIndex {
  int p;
  int q;
};

PlaneIndex planeIndex(const mbrt_ctx& ctx);

/// G20/G21: re-expresses the position, the offsets and the frames in the
/// new unit.
void switchUnits(mbrt_ctx& ctx, bool inch);

/// Moves in the modal motion mode (G00..G03) to the block's end point.
mbrt_status executeMotion(mbrt_ctx& ctx, const MotionWords& words);

/// The position of every axis as the program commands it: local
/// coordinates before mirror, scaling and rotation (frames.h).
const AxisCounts& programPosition(const mbrt_ctx& ctx);

/// Cutter compensation's moves (cutter_comp.h): the control point goes
/// straight, or on an arc about `center` (the plane's axes), to a position
/// in the workpiece frame, as the block of `origin` commanded.
void moveWorkStraight(mbrt_ctx& ctx, const AxisCounts& work, bool rapid,
                      const MoveOrigin& origin);
void moveWorkArc(mbrt_ctx& ctx, const AxisCounts& work, PlanePoint center,
                 bool clockwise, const MoveOrigin& origin);

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

/// Advances the simulated clock by a dwell.
void dwell(mbrt_ctx& ctx, double seconds);

} // namespace mbc::rt
