#include "runner/arc_geometry.h"

#include <cmath>
#include <numbers>

namespace mbc::runner {

int axisNamed(const mbrt_motion& m, char letter) {
  for (int axis = 0; axis < m.axis_count; ++axis) {
    if (m.axis_names[axis] == letter) {
      return axis;
    }
  }
  return -1;
}

bool isLatheMotion(const mbrt_motion& m) {
  return axisNamed(m, 'Y') < 0 && axisNamed(m, 'X') >= 0 &&
         axisNamed(m, 'Z') >= 0;
}

mbrt_motion inRadii(const mbrt_motion& m) {
  mbrt_motion out = m;
  for (int axis = 0; axis < m.axis_count; ++axis) {
    if ((m.diameter_mask >> axis & 1) != 0) {
      out.end[axis] /= 2.0;
      out.start[axis] /= 2.0;
      out.machine[axis] /= 2.0;
      out.programmed[axis] /= 2.0;
      for (int i = 0; i < 2; ++i) {
        if (m.center_axes[i] == m.axis_names[axis]) {
          out.center[i] /= 2.0;
        }
      }
    }
  }
  return out;
}

Arc arcOf(const mbrt_motion& m) {
  Arc arc;
  arc.p = axisNamed(m, m.center_axes[0]);
  arc.q = axisNamed(m, m.center_axes[1]);
  const double sx = m.start[arc.p] - m.center[0];
  const double sy = m.start[arc.q] - m.center[1];
  const double ex = m.end[arc.p] - m.center[0];
  const double ey = m.end[arc.q] - m.center[1];
  arc.radius = std::hypot(sx, sy);
  arc.begin = std::atan2(sy, sx);
  const bool ccw = m.kind == MBRT_MOTION_CCW;
  double sweep =
      ccw ? std::atan2(ey, ex) - arc.begin : arc.begin - std::atan2(ey, ex);
  constexpr double kTurn = 2.0 * std::numbers::pi;
  sweep = std::fmod(sweep + 2.0 * kTurn, kTurn);
  if (sweep < 1e-12) {
    sweep = kTurn; // start == end: a full circle
  }
  arc.sweep = ccw ? sweep : -sweep;
  return arc;
}

std::array<double, MBRT_MAX_AXES> arcPoint(const mbrt_motion& m, const Arc& arc,
                                           double t) {
  std::array<double, MBRT_MAX_AXES> point{};
  for (int axis = 0; axis < m.axis_count; ++axis) {
    point[axis] = m.start[axis] + t * (m.end[axis] - m.start[axis]);
  }
  const double angle = arc.begin + t * arc.sweep;
  point[arc.p] = m.center[0] + arc.radius * std::cos(angle);
  point[arc.q] = m.center[1] + arc.radius * std::sin(angle);
  return point;
}

std::vector<double> extremes(const Arc& arc) {
  std::vector<double> fractions;
  constexpr double kTurn = 2.0 * std::numbers::pi;
  for (int quarter = 0; quarter < 4; ++quarter) {
    const double angle = quarter * kTurn / 4.0;
    const double ahead = arc.sweep > 0 ? angle - arc.begin : arc.begin - angle;
    const double t =
        std::fmod(ahead + 2.0 * kTurn, kTurn) / std::fabs(arc.sweep);
    if (t <= 1.0) {
      fractions.push_back(t);
    }
  }
  return fractions;
}

} // namespace mbc::runner
