// Cutter compensation C's part of the context: the moves it holds until
// the next move in the plane says where their end vector goes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "context.h"
#include "move_state.h"

namespace mbc::rt {

/// A programmed move as cutter compensation holds it (cutter_comp.h), in
/// the workpiece frame. `still`: no motion in the compensation plane (a Z
/// move, or a block without motion, which is not held).
struct HeldMove {
  bool still = false;
  bool arc = false;
  bool clockwise = false; // as it turns in the workpiece frame
  bool rapid = false;
  bool startUp =
      false;          // the first move with the offset: no vector at its start
  AxisCounts start{}; // programmed, workpiece frame
  AxisCounts end{};
  double center[2] = {0.0, 0.0}; // arcs: in the plane, workpiece counts
  bool hasDirection = false;     // G40/G41/G42 I J K: a virtual path
  double direction[2] = {0.0, 0.0};
  double offset = 0.0; // the offset value, counts (0 or more)
  int side = 1;        // 1: tool left of the path, -1: right
  MoveOrigin origin;   // origin.program is set from `program` as it leaves
  std::string program; // the program it was read in
  Placement placement; // of the block it was read in
  // A lathe's imaginary tip vector, added to the move's points so that
  // the offset path is the tip's (cutter_comp.cpp followTip).
  AxisCounts tipShift{};
};

/// Cutter compensation C: the move whose end vector waits for the next move
/// in the plane, and the moves without plane motion read after it.
struct CompensationState {
  bool engaged = false;          // the tool is offset from the programmed path
  std::vector<HeldMove> held;    // held.front() moves in the plane
  std::vector<HeldMove> leaving; // the moves leaving now (cutter_comp.cpp)
  int stillBlocks = 0;           // blocks without plane motion since it
  std::uint64_t planeMoves = 0;  // moves in the plane read so far
  bool codeInBlock = false;      // the block has G40, G41 or G42
};

/// Whether moves go through compensation: G41 or G42 in force, or the tool
/// still offset after G40 until the next move in the plane. Not while a
/// lathe's shape cycle reads its shape program: its moves are the
/// programmed shape, which the cycle compensates as a whole.
inline bool compensating(const mbrt_ctx& ctx) {
  // The modal code first: most blocks of most programs are in G40.
  return (ctx.machine.modal.compensation != 40 || ctx.compensation->engaged) &&
         !ctx.run.readingShape();
}

} // namespace mbc::rt
