// The names of the offset memory's entries, as the machine profile and the
// state file (mbc run --state) write them: work offsets "EXT", "G54".."G59",
// "G54.1P1".."G54.1P300"; a mill's tool offset fields "h_geometry",
// "h_wear", "d_geometry", "d_wear" by offset memory type; a lathe's
// "x_wear".."tip" and, with geometry and wear memory, "x_geometry"...
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "profile.h"

namespace mbc::rt {

/// The index in the work offset table of a key, none for another string.
std::optional<int> workOffsetIndex(std::string_view key);

/// The key of an index of the work offset table.
std::string workOffsetKey(int index);

/// A mill's tool offset field and the G10 L that writes it.
struct MillOffsetKey {
  const char* key;
  double ToolOffset::*field;
  int l;
};

/// A lathe's tool offset field, whether it is a geometry offset (G10 P
/// 10000 + n) and the G10 word that writes it ('Q' for the tip).
struct LatheOffsetKey {
  const char* key;
  double LatheOffset::*field;
  bool geometry;
  char letter;
};

/// The fields memory A (one value per offset, for H and D), B (a geometry
/// and a wear that H and D share) or C (all four) has.
std::span<const MillOffsetKey> millOffsetKeys(char memory);

/// A lathe's fields: the wear and the tip, and the geometry when the
/// memory has geometry and wear.
std::span<const LatheOffsetKey> latheOffsetKeys(bool geometryWear);

/// The entry of a field.
const MillOffsetKey& millOffsetKey(double ToolOffset::*field);
const LatheOffsetKey& latheOffsetKey(double LatheOffset::*field);

} // namespace mbc::rt
