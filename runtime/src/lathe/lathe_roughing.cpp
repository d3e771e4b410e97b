// Roughing paths of a lathe's shape cycles (lathe_roughing.h). G72 is G71
// with the axes exchanged: the shape is swapped into G71's frame (cuts
// along z, steps in x), roughed, and the path swapped back.
#include "lathe_roughing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "shape_geometry.h"

namespace mbc::rt {

namespace {

ShapePoint swapped(ShapePoint p) {
  return {p.z, p.x};
}

/// A move in the other frame: swapping the axes mirrors the plane, so arcs
/// turn the other way.
ShapeMove swapped(ShapeMove move) {
  move.end = swapped(move.end);
  move.center = swapped(move.center);
  move.motion = mirrored(move.motion);
  return move;
}

Shape swapAxes(const Shape& shape) {
  Shape out{swapped(shape.start), {}, shape.file};
  for (const ShapeMove& move : shape.moves) {
    out.moves.push_back(swapped(move));
  }
  return out;
}

/// Where the contour first reaches the level x (along the contour), or
/// nothing when it never does.
std::optional<double> levelHit(const std::vector<ShapeMove>& contour,
                               ShapePoint from, double x) {
  for (const ShapeMove& move : contour) {
    const ShapePoint to = move.end;
    if (!isArc(move)) {
      if (from.x == x) {
        return from.z;
      }
      if ((from.x - x) * (to.x - x) < 0.0) {
        return from.z + (x - from.x) * (to.z - from.z) / (to.x - from.x);
      }
    } else {
      const ShapePoint c = move.center;
      const double r = std::hypot(from.x - c.x, from.z - c.z);
      const double dx = x - c.x;
      if (std::fabs(dx) <= r) {
        const double dz = std::sqrt(r * r - dx * dx);
        const double begin = angleOf(from, c);
        const double sweep = sweepOf(move, from);
        std::optional<double> best;
        double bestTravel = 0.0;
        for (const double z : {c.z + dz, c.z - dz}) {
          const double angle = std::atan2(dx, z - c.z);
          if (onArc(angle, begin, sweep)) {
            const double travel = std::fabs(angle - begin);
            if (!best || travel < bestTravel) {
              best = z;
              bestTravel = travel;
            }
          }
        }
        if (best) {
          return best;
        }
      }
    }
    from = to;
  }
  return from.x == x ? std::optional<double>(from.z) : std::nullopt;
}

/// Whether x never turns back along the contour (arcs by their extremes).
bool monotonic(const std::vector<ShapeMove>& contour, ShapePoint from) {
  int direction = 0;
  const auto step = [&](double a, double b) {
    if (a == b) {
      return true;
    }
    const int d = b > a ? 1 : -1;
    if (direction == 0) {
      direction = d;
    }
    return d == direction;
  };
  for (const ShapeMove& move : contour) {
    if (isArc(move)) {
      // An arc passing 90 or 270 degrees (x extreme) turns x back.
      const double begin = angleOf(from, move.center);
      const double sweep = sweepOf(move, from);
      for (const double extreme :
           {std::numbers::pi / 2.0, -std::numbers::pi / 2.0}) {
        if (onArc(extreme, begin, sweep) &&
            std::fabs(angleOf(move.end, move.center) - extreme) > 1e-9 &&
            std::fabs(begin - extreme) > 1e-9) {
          return false;
        }
      }
    }
    if (!step(from.x, move.end.x)) {
      return false;
    }
    from = move.end;
  }
  return true;
}

ShapeFault roughTurning(const Shape& shape, const Roughing& roughing,
                        std::vector<ShapeMove>& out) {
  if (shape.moves.empty()) {
    return ShapeFault::None;
  }
  const ShapePoint a = shape.start;
  const ShapeMove& first = shape.moves.front();
  // The contour: the shape after A', shifted by the allowance.
  const ShapePoint startC = shifted(first.end, roughing.allowance);
  std::vector<ShapeMove> contour;
  for (std::size_t i = 1; i < shape.moves.size(); ++i) {
    ShapeMove move = shape.moves[i];
    move.end = shifted(move.end, roughing.allowance);
    move.center = shifted(move.center, roughing.allowance);
    contour.push_back(move);
  }
  if (!monotonic(contour, startC)) {
    return ShapeFault::NotMonotonic;
  }
  const ShapePoint endC = contour.empty() ? startC : contour.back().end;
  const double sx = a.x >= startC.x ? 1.0 : -1.0; // cuts go towards -sx
  const double dz = endC.z <= a.z ? -1.0 : 1.0;   // along z to the end
  const ShapeMotion approach = first.motion == ShapeMotion::Rapid
                                   ? ShapeMotion::Rapid
                                   : ShapeMotion::Line;
  for (double level = a.x - sx * roughing.depth; sx * (level - startC.x) > 0.0;
       level -= sx * roughing.depth) {
    const double stop = levelHit(contour, startC, level).value_or(endC.z);
    out.push_back(straightTo(approach, {level, a.z}));
    out.push_back(straightTo(ShapeMotion::Line, {level, stop}));
    out.push_back(
        straightTo(ShapeMotion::Rapid, {level + sx * roughing.escape,
                                        stop - dz * roughing.escape}));
    out.push_back(
        straightTo(ShapeMotion::Rapid, {level + sx * roughing.escape, a.z}));
  }
  // Along the shape with the allowance left on it, then back to A.
  out.push_back(straightTo(approach, startC));
  for (ShapeMove move : contour) {
    move.feed = 0.0; // the cycle's F
    if (move.motion == ShapeMotion::Rapid) {
      move.motion = ShapeMotion::Line;
    }
    out.push_back(move);
  }
  out.push_back(straightTo(ShapeMotion::Rapid, a));
  return ShapeFault::None;
}

} // namespace

ShapeFault roughShape(const Shape& shape, const Roughing& roughing,
                      std::vector<ShapeMove>& out) {
  const auto rough = roughing.pockets ? roughPockets : roughTurning;
  if (!roughing.facing) {
    return rough(shape, roughing, out);
  }
  Roughing swappedRoughing = roughing;
  swappedRoughing.allowance = swapped(roughing.allowance);
  std::vector<ShapeMove> path;
  const ShapeFault fault = rough(swapAxes(shape), swappedRoughing, path);
  for (const ShapeMove& move : path) {
    out.push_back(swapped(move));
  }
  return fault;
}

void repeatShape(const Shape& shape, ShapePoint allowance, ShapePoint relief,
                 int divisions, std::vector<ShapeMove>& out) {
  for (int pass = 1; pass <= divisions; ++pass) {
    const double share =
        divisions > 1 ? static_cast<double>(divisions - pass) / (divisions - 1)
                      : 0.0;
    const ShapePoint by{allowance.x + relief.x * share,
                        allowance.z + relief.z * share};
    for (ShapeMove move : shape.moves) {
      move.end = shifted(move.end, by);
      move.center = shifted(move.center, by);
      move.feed = 0.0;
      out.push_back(move);
    }
    out.push_back(straightTo(ShapeMotion::Rapid, shape.start));
  }
}

} // namespace mbc::rt
