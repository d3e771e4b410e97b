// What a G31 probe can touch (docs/machine-profile.md "probe"): solids in
// machine coordinates (mm) and a stylus ball of a radius. A move touches
// at the first point where the ball meets a solid.
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace mbc::rt {

using Point3 = std::array<double, 3>; // X, Y, Z in mm

struct ProbeShape {
  enum class Kind { Box, Cylinder, Bore, Sphere, Plane };
  Kind kind = Kind::Box;
  Point3 a{};          // box min; cylinder/bore/sphere centre; plane point
  Point3 b{};          // box max; plane normal (unit, out of the material)
  double radius = 0.0; // cylinder, bore, sphere
  double bottom = 0.0; // cylinder and bore: the Z range of the material
  double top = 0.0;
  int signal = 1; // the skip signal it gives: G31 (P1) to G31 P4
};

struct ProbeScene {
  double radius = 0.0; // of the stylus ball
  std::vector<ProbeShape> shapes;
};

/// The skip signals a G31 can wait for: plain G31 is P1, the multi-step
/// skip has P1 to P4.
inline constexpr int kSkipSignals = 4;

/// How far the ball centre at `point` may move in any direction before the
/// ball touches a solid that gives skip signal `signal`: exact or too small,
/// never too large; <= 0 in contact.
double clearance(const ProbeScene& scene, const Point3& point, int signal = 1);

/// The fraction 0..1 of the straight move from `from` to `to` at which the
/// ball first touches a solid that gives `signal`, nullopt when it never
/// does.
std::optional<double> firstContact(const ProbeScene& scene, const Point3& from,
                                   const Point3& to, int signal = 1);

} // namespace mbc::rt
