// The stored stroke check 1 (stroke_check.h), in counts of the machine's
// coordinates: a stroke's ends are converted once per move, the positions
// never.
#include "stroke_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mbc::rt {

namespace {

struct Stroke {
  double low;
  double high;
};

/// Where a move first passes an end of a stroke.
struct Overtravel {
  double share = 2.0; // of the move gone by then; beyond 1: it stays within
  int axis = -1;
  bool plus = false;
  double reach = 0.0; // the farthest the move would take the axis
};

void keepFirst(Overtravel& first, const Overtravel& found) {
  if (found.share < first.share) {
    first = found;
  }
}

/// The ends an axis must not pass on a move from `from`: its stroke's, or
/// `from` where the tool stands beyond an end (the stroke was set with the
/// tool there), so that it may come back but go no farther.
Stroke boundsFrom(Stroke stroke, double from) {
  return {std::min(stroke.low, from), std::max(stroke.high, from)};
}

void checkStraight(Overtravel& first, int axis, double from, double to,
                   Stroke stroke) {
  const Stroke bounds = boundsFrom(stroke, from);
  if (to > bounds.high) {
    keepFirst(first, {(bounds.high - from) / (to - from), axis, true, to});
  } else if (to < bounds.low) {
    keepFirst(first, {(bounds.low - from) / (to - from), axis, false, to});
  }
}

/// An arc from angle `begin` about its centre, turning `turn` (1
/// counterclockwise, -1 clockwise) through `sweep` radians.
struct ArcSpan {
  double radius;
  double begin;
  double turn;
  double sweep;

  /// How far the arc turns to reach angle `a` (0 to 2 pi).
  double travelTo(double a) const {
    return withinTurn(turn * (a - begin) + 4.0 * std::numbers::pi);
  }
};

/// A plane axis of an arc: at angle `a` about the centre it stands at
/// base + radius cos(a - phase), phase 0 for the plane's first axis and
/// pi / 2 for its second. It is farthest out at `phase` and `phase` + pi
/// where the arc passes them, and crosses a level going out where the
/// cosine's slope along the turn has the way out's sign.
void checkArcAxis(Overtravel& first, int axis, const ArcSpan& arc, double base,
                  double phase, double from, Stroke stroke) {
  const auto at = [&](double a) {
    return base + arc.radius * std::cos(a - phase);
  };
  const double end = at(arc.begin + arc.turn * arc.sweep);
  const double start = at(arc.begin);
  const double high = arc.travelTo(phase) <= arc.sweep ? base + arc.radius
                                                       : std::max(start, end);
  const double low = arc.travelTo(phase + std::numbers::pi) <= arc.sweep
                         ? base - arc.radius
                         : std::min(start, end);
  const auto shareAt = [&](double level, bool plus) {
    const double cosine = std::clamp((level - base) / arc.radius, -1.0, 1.0);
    const double travel =
        arc.travelTo(phase + (plus ? -arc.turn : arc.turn) * std::acos(cosine));
    // Past the sweep only by rounding, at the start.
    return travel <= arc.sweep ? travel / arc.sweep : 0.0;
  };
  const Stroke bounds = boundsFrom(stroke, from);
  if (high > bounds.high) {
    keepFirst(first, {shareAt(bounds.high, true), axis, true, high});
  }
  if (low < bounds.low) {
    keepFirst(first, {shareAt(bounds.low, false), axis, false, low});
  }
}

/// Calls `check(axis, stroke)` for each axis with a stroke.
template <typename Check> void forEachStroke(const mbrt_ctx& ctx, Check check) {
  const std::uint32_t mask = ctx.profile.strokeAxes();
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((mask >> axis & 1) != 0) {
      const double scale = ctx.boxScale(axis, ctx.machine.modal.inch);
      const auto i = static_cast<std::size_t>(axis);
      check(axis, Stroke{ctx.profile.strokeLow[i] * scale,
                         ctx.profile.strokeHigh[i] * scale});
    }
  }
}

mbrt_status report(mbrt_ctx& ctx, const Overtravel& first,
                   const MoveOrigin& origin) {
  if (first.axis < 0) {
    return 0;
  }
  const auto i = static_cast<std::size_t>(first.axis);
  return raiseAt(
      ctx, {origin.file, origin.line},
      first.plus ? AlarmId::OvertravelPlus : AlarmId::OvertravelMinus,
      fmt::format(
          "{} would reach {:.3f} {} in machine coordinates, past the "
          "{} end of its stroke, {:.3f} (parameter {})",
          ctx.profile.axes[i],
          first.reach / ctx.boxScale(first.axis, ctx.machine.modal.inch),
          ctx.isRotary(first.axis) ? "deg" : "mm", first.plus ? '+' : '-',
          first.plus ? ctx.profile.strokeHigh[i] : ctx.profile.strokeLow[i],
          first.plus ? 1320 : 1321));
}

} // namespace

mbrt_status checkLineStroke(mbrt_ctx& ctx, const AxisCounts& machine,
                            const MoveOrigin& origin) {
  Overtravel first;
  forEachStroke(ctx, [&](int axis, Stroke stroke) {
    checkStraight(first, axis, static_cast<double>(ctx.machine.position[axis]),
                  static_cast<double>(machine[axis]), stroke);
  });
  return report(ctx, first, origin);
}

mbrt_status checkArcStroke(mbrt_ctx& ctx, const AxisCounts& work,
                           const AxisCounts& machine, const ArcPath& arc,
                           const MoveOrigin& origin) {
  const PlanePoint offset = arc.from - arc.center;
  const ArcSpan span{length(offset), std::atan2(offset.y, offset.x),
                     arc.clockwise ? -1.0 : 1.0, arc.sweep};
  Overtravel first;
  forEachStroke(ctx, [&](int axis, Stroke stroke) {
    const auto from = static_cast<double>(ctx.machine.position[axis]);
    if (axis != arc.p && axis != arc.q) {
      checkStraight(first, axis, from, static_cast<double>(machine[axis]),
                    stroke);
      return;
    }
    // The workpiece frame is the machine's moved: the arc keeps its shape.
    const auto shift = static_cast<double>(machine[axis] - work[axis]);
    const bool firstAxis = axis == arc.p;
    checkArcAxis(first, axis, span,
                 shift + (firstAxis ? arc.center.x : arc.center.y),
                 firstAxis ? 0.0 : std::numbers::pi / 2.0, from, stroke);
  });
  return report(ctx, first, origin);
}

} // namespace mbc::rt
