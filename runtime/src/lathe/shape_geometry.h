// Small pieces of plane geometry that the shape cycles' roughing (type I in
// lathe_roughing.cpp, the pockets of type II in lathe_pockets.cpp) share.
#pragma once

#include <cmath>
#include <numbers>

#include "lathe_shape.h"

namespace mbc::rt {

inline ShapePoint shifted(ShapePoint p, ShapePoint by) {
  return {p.x + by.x, p.z + by.z};
}

/// A straight move of a cycle's path, at the cycle's F.
inline ShapeMove straightTo(ShapeMotion motion, ShapePoint end) {
  ShapeMove move;
  move.motion = motion;
  move.end = end;
  return move;
}

inline bool isArc(const ShapeMove& move) {
  return move.motion == ShapeMotion::Clockwise ||
         move.motion == ShapeMotion::CounterClockwise;
}

/// The other turning sense: what an arc becomes when one axis is mirrored.
inline ShapeMotion mirrored(ShapeMotion motion) {
  return motion == ShapeMotion::Clockwise ? ShapeMotion::CounterClockwise
         : motion == ShapeMotion::CounterClockwise ? ShapeMotion::Clockwise
                                                   : motion;
}

/// The angle of a point about a centre, in the ZX plane's own sense (z the
/// first axis).
inline double angleOf(ShapePoint p, ShapePoint c) {
  return std::atan2(p.x - c.x, p.z - c.z);
}

/// The signed sweep of an arc move from `from` (counter-clockwise
/// positive).
inline double sweepOf(const ShapeMove& move, ShapePoint from) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const double begin = angleOf(from, move.center);
  const double end = angleOf(move.end, move.center);
  double sweep = end - begin;
  if (move.motion == ShapeMotion::CounterClockwise) {
    while (sweep <= 0.0) {
      sweep += kTurn;
    }
  } else {
    while (sweep >= 0.0) {
      sweep -= kTurn;
    }
  }
  return sweep;
}

/// Whether `angle` lies on the arc from `begin` turning `sweep`.
inline bool onArc(double angle, double begin, double sweep) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  double travel = sweep > 0.0 ? angle - begin : begin - angle;
  travel = std::fmod(std::fmod(travel, kTurn) + kTurn, kTurn);
  return travel <= std::fabs(sweep) + 1e-12;
}

} // namespace mbc::rt
