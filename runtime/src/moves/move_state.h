// The state a move owns: the placement of the block it was read in and
// the block's data (feed, spindle, line), which a move that waits for later
// blocks keeps whatever they change (held_block.h, cutter_comp.h).
#pragma once

#include "context.h"
#include "plane_geometry.h"

namespace mbc::rt {

/// An arc of the plane axes `p` and `q` (indexes into positions) about
/// `center`, from `from` (workpiece counts), turning `sweep` radians.
struct ArcPath {
  int p, q;
  PlanePoint center, from;
  double sweep;
  bool clockwise;
};

/// Where a block's points go on the machine: its frames (G52, G92, mirror,
/// scaling, rotation, the tool length offset, a lathe's tool offsets) and
/// the values of its work offset and of the external offset. A move that
/// waits for later blocks keeps the placement of its own block, whatever
/// they change (frames.h PlacedAs).
struct Placement {
  Frames frames;
  AxisCounts workOffset{};
  AxisCounts external{};
};

/// Where a move was programmed and how fast it goes: the block's data, kept
/// with a move that cutter compensation holds while later blocks run.
struct MoveOrigin {
  const char* file = nullptr;
  int line = 0;
  const char* program = "";
  double feed = 0.0;  // modal F
  int feedMode = 94;  // G93 G94 G95
  double spindle = 0; // S, for G95
  int cycle = 0;      // the canned cycle a move belongs to
  // The block's programmed end point (workpiece frame) when the move's end
  // is elsewhere: cutter compensation's tool centre.
  const AxisCounts* programmed = nullptr;
  // A lathe's spindle: in G96 `spindle` is the surface speed and the speed
  // at each X follows from it, capped at `spindleLimit` (0: none); a G32
  // thread's F is its lead along its longer axis.
  bool surfaceSpeed = false;
  double spindleLimit = 0.0;
  bool threading = false;
  double leadChange = 0.0; // G34 K: the lead grows by it per revolution
};

/// The state of the block a held chamfer or corner R was read in, which
/// its moves run in while the next block is read: the modal codes (F,
/// G94/G95, the plane, G40-G42...), the placement, the D and S in force,
/// and whether the block gave G40-G42 or F (held_block.h).
struct BlockState {
  ModalState modal;
  Placement placement;
  double dWord = 0.0; // #4107
  double sWord = 0.0; // #4119
  bool codeInBlock = false;
  bool feedInBlock = false;
};

} // namespace mbc::rt
