// The names of the offset memory's entries (offset_keys.h).
#include "offset_keys.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "profile_json.h"

namespace mbc::rt {

namespace {

// In the order of the memory types: A has the first, B the first two.
constexpr std::array<MillOffsetKey, 4> kMillKeys = {{
    {"h_geometry", &ToolOffset::hGeometry, 10},
    {"h_wear", &ToolOffset::hWear, 11},
    {"d_geometry", &ToolOffset::dGeometry, 12},
    {"d_wear", &ToolOffset::dWear, 13},
}};

// The wear and the tip first: without geometry and wear memory an offset
// has these only.
constexpr std::array<LatheOffsetKey, 9> kLatheKeys = {{
    {"x_wear", &LatheOffset::xWear, false, 'X'},
    {"z_wear", &LatheOffset::zWear, false, 'Z'},
    {"y_wear", &LatheOffset::yWear, false, 'Y'},
    {"r_wear", &LatheOffset::rWear, false, 'R'},
    {"tip", &LatheOffset::tip, false, 'Q'},
    {"x_geometry", &LatheOffset::xGeometry, true, 'X'},
    {"z_geometry", &LatheOffset::zGeometry, true, 'Z'},
    {"y_geometry", &LatheOffset::yGeometry, true, 'Y'},
    {"r_geometry", &LatheOffset::rGeometry, true, 'R'},
}};
constexpr std::size_t kLatheWearKeys = 5;

constexpr std::string_view kG541Prefix = "G54.1P";

} // namespace

std::optional<int> workOffsetIndex(std::string_view key) {
  if (key == "EXT") {
    return kExternalOffset;
  }
  if (key.size() == 3 && key.substr(0, 2) == "G5" && key[2] >= '4' &&
      key[2] <= '9') {
    return kFirstG54Offset + (key[2] - '4');
  }
  if (key.substr(0, kG541Prefix.size()) == kG541Prefix) {
    const auto p = keyNumber(key.substr(kG541Prefix.size()));
    if (p && *p >= 1 && *p <= kG541Count) {
      return kFirstG541Offset + *p - 1;
    }
  }
  return std::nullopt;
}

std::string workOffsetKey(int index) {
  if (index == kExternalOffset) {
    return "EXT";
  }
  if (index < kFirstG541Offset) {
    return fmt::format("G{}", 54 + index - kFirstG54Offset);
  }
  return fmt::format("{}{}", kG541Prefix, index - kFirstG541Offset + 1);
}

std::span<const MillOffsetKey> millOffsetKeys(char memory) {
  const std::size_t count = memory == 'A' ? 1 : memory == 'B' ? 2 : 4;
  return {kMillKeys.data(), count};
}

std::span<const LatheOffsetKey> latheOffsetKeys(bool geometryWear) {
  return {kLatheKeys.data(), geometryWear ? kLatheKeys.size() : kLatheWearKeys};
}

const MillOffsetKey& millOffsetKey(double ToolOffset::*field) {
  return *std::find_if(
      kMillKeys.begin(), kMillKeys.end(),
      [&](const MillOffsetKey& k) { return k.field == field; });
}

const LatheOffsetKey& latheOffsetKey(double LatheOffset::*field) {
  return *std::find_if(
      kLatheKeys.begin(), kLatheKeys.end(),
      [&](const LatheOffsetKey& k) { return k.field == field; });
}

} // namespace mbc::rt
