// The profile JSON readers shared by profile.cpp and probe_scene.cpp.
#include "profile_json.h"

#include <charconv>
#include <cmath>

namespace mbc::rt {

using nlohmann::json;

void fail(const std::string& key, const std::string& what) {
  throw ProfileError("machine profile: \"" + key + "\" " + what);
}

void unknownKey(const std::string& path) {
  throw ProfileError("machine profile: unknown key \"" + path + "\"");
}

std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

const json& object(const json& value, const std::string& path) {
  if (!value.is_object()) {
    fail(path, "must be an object");
  }
  return value;
}

double number(const json& value, const std::string& path) {
  if (!value.is_number()) {
    fail(path, "must be a number");
  }
  return value.get<double>();
}

int integer(const json& value, const std::string& path, int low, int high) {
  const double x = number(value, path);
  if (x != std::floor(x) || x < low || x > high) {
    fail(path, "must be a whole number from " + std::to_string(low) + " to " +
                   std::to_string(high));
  }
  return static_cast<int>(x);
}

bool boolean(const json& value, const std::string& path) {
  if (!value.is_boolean()) {
    fail(path, "must be true or false");
  }
  return value.get<bool>();
}

std::optional<int> keyNumber(std::string_view key) {
  int n = 0;
  const auto [end, ec] =
      std::from_chars(key.data(), key.data() + key.size(), n);
  if (ec != std::errc() || end != key.data() + key.size()) {
    return std::nullopt;
  }
  return n;
}

} // namespace mbc::rt
