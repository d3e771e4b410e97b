// Chamfering and corner R's part of the context: the move a corner holds
// until the next block says where the corner goes.
#pragma once

#include <array>

#include "context.h"
#include "move_state.h"

namespace mbc::rt {

/// Chamfering and corner R (lathe_corners.h): the G01 block with I, K
/// (C) or R holds its move until the next block tells where the corner
/// goes. Program coordinates; `amount` signed along `toward`.
struct CornerInsertion {
  bool pending = false;
  bool fresh = false;  // held by the block running now
  bool round = false;  // corner R, else a chamfer
  AxisCounts from{};   // the held move's start (a)
  AxisCounts corner{}; // its end (b), where the next block starts
  int along = -1;      // the axis the held move runs on
  int toward = -1;     // the axis of the next move
  Counts amount = 0;
  const char* file = nullptr; // the held block's
  int line = 0;
  BlockState block; // the held block's state, which its moves run in
  // ,C or ,R (corner_blends.h): 'C' or 'R', at any angle, after a line or
  // an arc about `center` (the plane's axes, counts); 0 for the 90 degree
  // forms above.
  char blend = 0;
  bool rapid = false; // a G00 ,A line
  bool arc = false;
  bool clockwise = false;
  std::array<double, 2> center{};
  // ,A without an end point: the line's angle; the next block's end point
  // and ,A give the corner.
  bool openEnd = false;
  double angle = 0.0;

  /// ,C ,R or an open ,A (corner_blends.h), not a 90 degree form.
  bool anyAngle() const { return blend != 0 || openEnd; }
};

} // namespace mbc::rt
