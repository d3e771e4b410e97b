// Probe contact by sphere tracing: every shape has a signed distance (a
// lower bound where exact would be costly), so stepping along the move by
// the clearance never passes through a surface, and flat or head-on
// approaches land on the contact in one step.
#include "probe_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "profile_json.h"

namespace mbc::rt {

namespace {

using nlohmann::json;

constexpr double kContact = 1e-9;    // mm: touching
constexpr int kMaxSteps = 1'000'000; // grazing moves converge slowly

double length(double x, double y, double z) {
  return std::sqrt(x * x + y * y + z * z);
}

/// Distance outside (> 0) or inside (< 0) of a vertical slab bottom..top.
double slab(const ProbeShape& s, double z) {
  const double middle = (s.bottom + s.top) / 2.0;
  return std::fabs(z - middle) - (s.top - s.bottom) / 2.0;
}

double distance(const ProbeShape& s, const Point3& p) {
  switch (s.kind) {
    case ProbeShape::Kind::Box: {
      double q[3];
      for (int i = 0; i < 3; ++i) {
        q[i] =
            std::fabs(p[i] - (s.a[i] + s.b[i]) / 2.0) - (s.b[i] - s.a[i]) / 2.0;
      }
      return length(std::max(q[0], 0.0), std::max(q[1], 0.0),
                    std::max(q[2], 0.0)) +
             std::min(std::max({q[0], q[1], q[2]}), 0.0);
    }
    case ProbeShape::Kind::Cylinder: {
      const double radial = std::hypot(p[0] - s.a[0], p[1] - s.a[1]) - s.radius;
      const double axial = slab(s, p[2]);
      return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0)) +
             std::min(std::max(radial, axial), 0.0);
    }
    case ProbeShape::Kind::Bore:
      // Material around the hole within the slab: a lower bound.
      return std::max(slab(s, p[2]),
                      s.radius - std::hypot(p[0] - s.a[0], p[1] - s.a[1]));
    case ProbeShape::Kind::Sphere:
      return length(p[0] - s.a[0], p[1] - s.a[1], p[2] - s.a[2]) - s.radius;
    case ProbeShape::Kind::Plane:
      return (p[0] - s.a[0]) * s.b[0] + (p[1] - s.a[1]) * s.b[1] +
             (p[2] - s.a[2]) * s.b[2];
  }
  return 0.0;
}

Point3 point3(const json& value, const std::string& path, std::size_t size) {
  if (!value.is_array() || value.size() != size) {
    fail(path, fmt::format("must be an array of {} numbers", size));
  }
  Point3 point{};
  for (std::size_t i = 0; i < size; ++i) {
    point[i] = number(value[i], fmt::format("{}[{}]", path, i));
  }
  return point;
}

double positive(const json& value, const std::string& path) {
  const double x = number(value, path);
  if (x <= 0.0) {
    fail(path, "must be positive");
  }
  return x;
}

/// "z": [bottom, top] of a cylinder or bore.
void zRange(const json& value, const std::string& path, ProbeShape& shape) {
  const Point3 range = point3(value, path, 2);
  if (range[0] >= range[1]) {
    fail(path, "must be [bottom, top] with bottom below top");
  }
  shape.bottom = range[0];
  shape.top = range[1];
}

using Kind = ProbeShape::Kind;

/// The shape kinds by their "type" name.
std::optional<Kind> kindNamed(const json& type) {
  static constexpr std::pair<const char*, Kind> kKinds[] = {
      {"box", Kind::Box},
      {"cylinder", Kind::Cylinder},
      {"bore", Kind::Bore},
      {"sphere", Kind::Sphere},
      {"plane", Kind::Plane}};
  for (const auto& [name, kind] : kKinds) {
    if (type == name) {
      return kind;
    }
  }
  return std::nullopt;
}

/// One key of a shape; false when the shape has no such key.
bool parseShapeKey(const std::string& key, const json& item,
                   const std::string& path, ProbeShape& shape) {
  const bool round = shape.kind == Kind::Cylinder || shape.kind == Kind::Bore;
  if (shape.kind == Kind::Box && (key == "min" || key == "max")) {
    (key == "min" ? shape.a : shape.b) = point3(item, path, 3);
  } else if (round && key == "center") {
    shape.a = point3(item, path, 2);
  } else if (round && key == "z") {
    zRange(item, path, shape);
  } else if (shape.kind == Kind::Sphere && key == "center") {
    shape.a = point3(item, path, 3);
  } else if ((round || shape.kind == Kind::Sphere) && key == "radius") {
    shape.radius = positive(item, path);
  } else if (shape.kind == Kind::Plane && (key == "point" || key == "normal")) {
    (key == "point" ? shape.a : shape.b) = point3(item, path, 3);
  } else {
    return false;
  }
  return true;
}

ProbeShape parseShape(const json& value, const std::string& path) {
  object(value, path);
  const std::optional<Kind> kind =
      value.contains("type") ? kindNamed(value["type"]) : std::nullopt;
  if (!kind) {
    fail(child(path, "type"),
         "must be \"box\", \"cylinder\", \"bore\", \"sphere\" or \"plane\"");
  }
  ProbeShape shape;
  shape.kind = *kind;
  for (const auto& [key, item] : value.items()) {
    if (key == "signal") {
      shape.signal = integer(item, child(path, key), 1, kSkipSignals);
    } else if (key != "type" &&
               !parseShapeKey(key, item, child(path, key), shape)) {
      unknownKey(child(path, key));
    }
  }
  if (shape.kind == Kind::Box) {
    for (int i = 0; i < 3; ++i) {
      if (shape.a[i] >= shape.b[i]) {
        fail(path, "must have min below max on every axis");
      }
    }
  } else if (shape.kind == Kind::Plane) {
    const double norm = length(shape.b[0], shape.b[1], shape.b[2]);
    if (norm == 0.0) {
      fail(child(path, "normal"), "must be given and not zero");
    }
    for (double& c : shape.b) {
      c /= norm;
    }
  } else if (shape.radius <= 0.0) {
    fail(child(path, "radius"), "must be given");
  }
  if ((shape.kind == Kind::Cylinder || shape.kind == Kind::Bore) &&
      shape.bottom >= shape.top) {
    fail(child(path, "z"), "must be given as [bottom, top]");
  }
  return shape;
}

} // namespace

double clearance(const ProbeScene& scene, const Point3& point, int signal) {
  double nearest = HUGE_VAL;
  for (const ProbeShape& shape : scene.shapes) {
    if (shape.signal == signal) {
      nearest = std::min(nearest, distance(shape, point));
    }
  }
  return nearest - scene.radius;
}

std::optional<double> firstContact(const ProbeScene& scene, const Point3& from,
                                   const Point3& to, int signal) {
  const double total =
      length(to[0] - from[0], to[1] - from[1], to[2] - from[2]);
  double travelled = 0.0;
  for (int step = 0; step < kMaxSteps; ++step) {
    const double f = total > 0.0 ? travelled / total : 0.0;
    const Point3 at{from[0] + f * (to[0] - from[0]),
                    from[1] + f * (to[1] - from[1]),
                    from[2] + f * (to[2] - from[2])};
    const double gap = clearance(scene, at, signal);
    if (gap <= kContact) {
      return f;
    }
    travelled += gap;
    if (travelled > total) {
      return std::nullopt;
    }
  }
  return total > 0.0 ? travelled / total : 0.0;
}

ProbeScene parseProbeScene(const json& value) {
  ProbeScene scene;
  for (const auto& [key, item] : object(value, "probe").items()) {
    const std::string path = child("probe", key);
    if (key == "radius") {
      scene.radius = number(item, path);
      if (scene.radius < 0.0) {
        fail(path, "must not be negative");
      }
    } else if (key == "scene") {
      if (!item.is_array()) {
        fail(path, "must be an array of shapes");
      }
      for (std::size_t i = 0; i < item.size(); ++i) {
        scene.shapes.push_back(
            parseShape(item[i], fmt::format("{}[{}]", path, i)));
      }
    } else {
      unknownKey(path);
    }
  }
  return scene;
}

} // namespace mbc::rt
