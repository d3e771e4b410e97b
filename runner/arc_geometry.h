// The geometry of a move that the pictures need: its axes by letter, and
// an arc's plane, radius, angles and points.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <vector>

namespace mbc::runner {

/// The index of the axis named `letter`, or -1.
int axisNamed(const mbrt_motion& m, char letter);

/// Whether the move is a lathe's: X and Z and no Y (its pictures are drawn
/// Z to the right, X up).
bool isLatheMotion(const mbrt_motion& m);

/// The move in its true geometry: a diameter axis (a lathe's X) halved to
/// the distance from the spindle axis, so that arcs are round.
mbrt_motion inRadii(const mbrt_motion& m);

/// An arc's plane axes, radius, start angle and signed sweep.
struct Arc {
  int p = -1;
  int q = -1;
  double radius = 0.0;
  double begin = 0.0;
  double sweep = 0.0; // > 0 counter-clockwise
};

/// The arc of a circular move (kind CW or CCW); a full circle when it ends
/// where it starts.
Arc arcOf(const mbrt_motion& m);

/// The point at fraction t of an arc: round in its plane, straight (helix)
/// on the other axes.
std::array<double, MBRT_MAX_AXES> arcPoint(const mbrt_motion& m, const Arc& arc,
                                           double t);

/// Where an arc passes 0, 90, 180 or 270 degrees, as fractions of it.
std::vector<double> extremes(const Arc& arc);

} // namespace mbc::runner
