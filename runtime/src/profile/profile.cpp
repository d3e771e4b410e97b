// Machine profile parsing (docs/machine-profile.md). Every key is optional;
// unknown keys and wrong types are errors that name the key, so that a typo
// in a profile never silently selects a default.
#include "profile.h"

#include <mbc/calling_codes.h>
#include <mbc/signals.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "offset_keys.h"
#include "parameters.h"
#include "profile_json.h"

namespace mbc::rt {

namespace {

using nlohmann::json;

void parseAxes(const json& value, Profile& profile) {
  const std::string what = "must be an array of 1 to 8 distinct axis "
                           "letters from XYZABCUVW";
  if (!value.is_array() || value.empty() || value.size() > MBRT_MAX_AXES) {
    fail("axes", what);
  }
  std::string axes;
  for (const json& axis : value) {
    if (!axis.is_string() || axis.get<std::string>().size() != 1) {
      fail("axes", what);
    }
    const char letter = axis.get<std::string>()[0];
    if (kAxisLetters.find(letter) == std::string_view::npos ||
        axes.find(letter) != std::string::npos) {
      fail("axes", what);
    }
    axes += letter;
  }
  profile.axes = axes;
}

void parseUnits(const json& value, Profile& profile) {
  if (value == "metric" || value == "inch") {
    profile.inch = value == "inch";
    return;
  }
  fail("units", "must be \"metric\" or \"inch\"");
}

void checkRange(const ParameterSpec& spec, double x, const std::string& path) {
  if (const std::optional<std::string> error = parameterValueError(spec, x)) {
    fail(path, *error);
  }
}

/// A per-axis parameter: an array of at most one number per axis.
void parseAxisParameter(const json& item, const std::string& path, int n,
                        const ParameterSpec& spec, Profile& profile) {
  if (!item.is_array() || item.size() > profile.axes.size()) {
    fail(path, fmt::format("must be an array of at most {} numbers, one per "
                           "axis",
                           profile.axes.size()));
  }
  AxisValues& values = profile.axisParameterValues(n);
  for (std::size_t axis = 0; axis < item.size(); ++axis) {
    const std::string itemPath = fmt::format("{}[{}]", path, axis);
    values[axis] = number(item[axis], itemPath);
    checkRange(spec, values[axis], itemPath);
  }
}

void parseParameters(const json& value, Profile& profile) {
  for (const auto& [key, item] : object(value, "parameters").items()) {
    const std::string path = child("parameters", key);
    const auto n = keyNumber(key);
    const ParameterSpec* spec = n ? findParameter(*n) : nullptr;
    if (spec == nullptr) {
      unknownKey(path);
    }
    if (spec->perAxis) {
      parseAxisParameter(item, path, *n, *spec, profile);
      continue;
    }
    const double x = number(item, path);
    checkRange(*spec, x, path);
    if (const std::optional<std::string> error = callingCodeError(*n, x)) {
      fail(path, *error);
    }
    profile.parameters[*n] = x;
  }
  const bool plus = profile.axisParameters.count(1320) != 0;
  if (plus != (profile.axisParameters.count(1321) != 0)) {
    fail(child("parameters", plus ? "1320" : "1321"),
         fmt::format("needs {} too: a stroke has two ends (give 1320 below "
                     "1321 on an axis without a stroke)",
                     plus ? 1321 : 1320));
  }
  deriveParameterFields(profile);
}

} // namespace

std::optional<std::string> parameterValueError(const ParameterSpec& spec,
                                               double x) {
  if ((spec.whole && x != std::floor(x)) || x < spec.low || x > spec.high) {
    return fmt::format("must be a{} number from {} to {}",
                       spec.whole ? " whole" : "", spec.low, spec.high);
  }
  return std::nullopt;
}

// The compiler keeps locals across the blocks that may call, by one rule
// (<mbc/calling_codes.h>); a code outside it must not call.
std::optional<std::string> callingCodeError(int n, double x) {
  const bool gCodes = n >= kCustomGCodes.firstParameter &&
                      n < kCustomGCodes.firstParameter + kCustomGCodes.size;
  if (gCodes && x != 0 &&
      !mayBeCustomGCode(static_cast<int>(std::fabs(x)) * 10)) {
    return fmt::format("must not be a G code mbc executes (G{})", std::fabs(x));
  }
  if (!gCodes && isCallingCodeParameter(n) && x != 0 && !mayBeCustomMCode(x)) {
    return fmt::format("must not be M{:02} (0 = no code)", x);
  }
  return std::nullopt;
}

void deriveParameterFields(Profile& profile) {
  profile.decimalPointInput = profile.parameterBit(3401, 0);
  profile.prt = profile.parameterBit(6001, 1);
  profile.nat = profile.parameterBit(6004, 0);
  profile.v15 = profile.parameterBit(6000, 3);
  profile.clearOnReset = profile.parameterBit(3402, 6);
  profile.rigidTappingCode = profile.parameter(5210);
  profile.strokeMask = 0;
  for (int axis = 0; axis < static_cast<int>(profile.axes.size()); ++axis) {
    const double high = profile.axisParameter(1320, axis);
    const double low = profile.axisParameter(1321, axis);
    if (high >= low) {
      profile.strokeMask |= std::uint32_t{1} << axis;
      profile.strokeLow[static_cast<std::size_t>(axis)] = low;
      profile.strokeHigh[static_cast<std::size_t>(axis)] = high;
    }
  }
  profile.codeCalls =
      profile.parameterBit(6001, 5) || profile.parameterBit(6007, 4) ||
      profile.parameterBit(6007, 5) ||
      std::any_of(profile.parameters.begin(), profile.parameters.end(),
                  [](const auto& p) {
                    return isCallingCodeParameter(p.first) && p.second != 0.0;
                  });
}

namespace {

/// The fields of the offset memory type (offset_keys.h).
void parseToolOffset(const json& value, const std::string& path, char memory,
                     ToolOffset& offset) {
  const auto keys = millOffsetKeys(memory);
  for (const auto& [key, item] : object(value, path).items()) {
    const std::string itemPath = child(path, key);
    // A structured binding is no lambda capture before clang 16.
    const std::string& name = key;
    const auto field = std::find_if(keys.begin(), keys.end(),
                                    [&](auto& k) { return name == k.key; });
    if (field == keys.end()) {
      unknownKey(itemPath);
    }
    offset.*(field->field) = number(item, itemPath);
  }
}

/// A lathe's offset: the geometry fields only with geometry_wear.
void parseLatheOffset(const json& value, const std::string& path,
                      bool geometryWear, LatheOffset& offset) {
  const auto keys = latheOffsetKeys(geometryWear);
  for (const auto& [key, item] : object(value, path).items()) {
    const std::string itemPath = child(path, key);
    // A structured binding is no lambda capture before clang 16.
    const std::string& name = key;
    const auto field = std::find_if(keys.begin(), keys.end(),
                                    [&](auto& k) { return name == k.key; });
    if (field == keys.end()) {
      unknownKey(itemPath);
    }
    offset.*(field->field) = number(item, itemPath);
  }
  if (offset.tip != std::floor(offset.tip) || offset.tip < 0 ||
      offset.tip > 9) {
    fail(child(path, "tip"), "must be a whole number from 0 to 9");
  }
}

/// A lathe's "tool_offsets": count (64 by default), geometry_wear and one
/// object per offset number.
void parseLatheOffsets(const json& offsets, Profile& profile) {
  profile.toolOffsetCount =
      offsets.contains("count")
          ? integer(offsets["count"], "tool_offsets.count", 1, kMaxToolOffsets)
          : kDefaultLatheOffsets;
  if (offsets.contains("geometry_wear")) {
    profile.geometryWear =
        boolean(offsets["geometry_wear"], "tool_offsets.geometry_wear");
  }
  profile.latheOffsets.assign(profile.toolOffsetCount + 1, LatheOffset{});
  for (const auto& [key, item] : offsets.items()) {
    if (key == "count" || key == "geometry_wear") {
      continue;
    }
    const std::string path = child("tool_offsets", key);
    const auto n = keyNumber(key);
    if (!n || *n < 1 || *n > profile.toolOffsetCount) {
      unknownKey(path);
    }
    parseLatheOffset(item, path, profile.geometryWear,
                     profile.latheOffsets[*n]);
  }
}

void parseToolOffsets(const json& value, Profile& profile) {
  const json& offsets = object(value, "tool_offsets");
  if (profile.lathe()) {
    parseLatheOffsets(offsets, profile);
    return;
  }
  if (offsets.contains("count")) {
    profile.toolOffsetCount =
        integer(offsets["count"], "tool_offsets.count", 1, kMaxToolOffsets);
  }
  if (offsets.contains("memory")) {
    const json& memory = offsets["memory"];
    if (memory != "A" && memory != "B" && memory != "C") {
      fail("tool_offsets.memory", "must be \"A\", \"B\" or \"C\"");
    }
    profile.toolOffsetMemory = memory.get<std::string>()[0];
  }
  profile.toolOffsets.assign(profile.toolOffsetCount + 1, ToolOffset{});
  for (const auto& [key, item] : offsets.items()) {
    if (key == "count" || key == "memory") {
      continue;
    }
    const std::string path = child("tool_offsets", key);
    const auto n = keyNumber(key);
    if (!n || *n < 1 || *n > profile.toolOffsetCount) {
      unknownKey(path);
    }
    parseToolOffset(item, path, profile.toolOffsetMemory,
                    profile.toolOffsets[*n]);
  }
}

void parseWorkOffsets(const json& value, Profile& profile) {
  for (const auto& [key, item] : object(value, "work_offsets").items()) {
    const std::string path = child("work_offsets", key);
    const auto index = workOffsetIndex(key);
    if (!index) {
      unknownKey(path);
    }
    if (!item.is_array() || item.size() > profile.axes.size()) {
      fail(path, "must be an array of at most one number per axis");
    }
    AxisValues& offset = profile.workOffsets[*index];
    for (std::size_t axis = 0; axis < item.size(); ++axis) {
      offset[axis] = number(item[axis], path);
      // Offsets become counts of the increment: nine digits at most.
      if (!(std::fabs(offset[axis]) < 100000.0)) {
        fail(path, "values must be between -99999.9999 and 99999.9999");
      }
    }
  }
}

void parseVariables(const json& value, Profile& profile) {
  for (const auto& [key, item] : object(value, "variables").items()) {
    const std::string path = child("variables", key);
    const auto n = keyNumber(key);
    if (!n || *n < 500 || *n > 999) {
      unknownKey(path);
    }
    profile.variables.emplace_back(*n, number(item, path));
  }
}

/// #1000-#1031: one signal, 0 or 1; #1032-#1035: 32 of them, a signed
/// 32-bit number.
void parseInputSignals(const json& value, Profile& profile) {
  for (const auto& [key, item] : object(value, "input_signals").items()) {
    const std::string path = child("input_signals", key);
    const auto n = keyNumber(key);
    if (!n || *n < kFirstInputSignal || *n > kLastInputWord) {
      unknownKey(path);
    }
    const double x = number(item, path);
    if (*n < kFirstInputWord ? x != 0.0 && x != 1.0 : !isSignalWord(x)) {
      fail(path, *n < kFirstInputWord
                     ? "must be 0 or 1 (one signal)"
                     : "must be a whole number of 32 bits (32 signals)");
    }
    profile.inputSignals.emplace_back(*n, x);
  }
}

void parseLimits(const json& value, Profile& profile) {
  for (const auto& [key, item] : object(value, "limits").items()) {
    const std::string path = child("limits", key);
    if (key == "macro_nesting") {
      profile.macroNesting = integer(item, path, 0, 100);
    } else if (key == "subprogram_nesting") {
      profile.subprogramNesting = integer(item, path, 0, 100);
    } else if (key == "total_nesting") {
      profile.totalNesting = integer(item, path, 0, 200);
    } else {
      unknownKey(path);
    }
  }
}

void parseParts(const json& value, Profile& profile) {
  for (const auto& [key, item] : object(value, "parts").items()) {
    const std::string path = child("parts", key);
    if (key == "count") {
      profile.partsCount = number(item, path);
    } else if (key == "required") {
      profile.partsRequired = number(item, path);
    } else {
      unknownKey(path);
    }
  }
}

/// 1006#0 ROT per axis when the profile gives 1006; otherwise A, B and C
/// are the rotary axes, as on most machines.
std::uint32_t rotaryAxes(const Profile& profile) {
  std::uint32_t mask = 0;
  const auto rot = profile.axisParameters.find(1006);
  for (std::size_t axis = 0; axis < profile.axes.size(); ++axis) {
    const bool rotary = rot != profile.axisParameters.end()
                            ? (static_cast<long>(rot->second[axis]) & 1) != 0
                            : std::string_view("ABC").find(
                                  profile.axes[axis]) != std::string_view::npos;
    mask |= rotary ? std::uint32_t{1} << axis : 0;
  }
  return mask;
}

/// 1006#3 DIA per axis when the profile gives 1006; otherwise a lathe's X
/// is programmed as a diameter.
std::uint32_t diameterAxes(const Profile& profile) {
  if (!profile.lathe()) {
    return 0;
  }
  const auto dia = profile.axisParameters.find(1006);
  if (dia == profile.axisParameters.end()) {
    const auto x = profile.axes.find('X');
    return x != std::string::npos ? std::uint32_t{1} << x : 0;
  }
  std::uint32_t mask = 0;
  for (std::size_t axis = 0; axis < profile.axes.size(); ++axis) {
    const bool diameter = (static_cast<long>(dia->second[axis]) & 8) != 0;
    mask |= diameter ? std::uint32_t{1} << axis : 0;
  }
  return mask;
}

/// "series": the T series is a lathe, by default with the axes X and Z.
void parseSeries(const json& root, Profile& profile) {
  if (!root.contains("series")) {
    return;
  }
  const json& value = root["series"];
  if (value != "M" && value != "T") {
    fail("series", "must be \"M\" (machining centre) or \"T\" (lathe)");
  }
  profile.series = static_cast<Series>(value.get<std::string>()[0]);
  if (profile.lathe()) {
    profile.axes = "XZ";
    profile.toolOffsetCount = kDefaultLatheOffsets;
    profile.latheOffsets.assign(kDefaultLatheOffsets + 1, LatheOffset{});
  }
}

/// What the T series adds once every key is read: the G code system and
/// the diameter axes.
void finishLathe(Profile& profile) {
  if (!profile.lathe()) {
    return;
  }
  if (profile.axes.find('X') == std::string::npos ||
      profile.axes.find('Z') == std::string::npos) {
    fail("axes", "must name X and Z on a lathe (\"series\": \"T\")");
  }
  if (profile.parameterBit(3401, 6) && profile.parameterBit(3401, 7)) {
    fail("parameters.3401", "must not set both bit 6 GSB and bit 7 GSC");
  }
  profile.gCodeSystem = profile.parameterBit(3401, 7)   ? 'C'
                        : profile.parameterBit(3401, 6) ? 'B'
                                                        : 'A';
}

Profile parseTopLevel(const json& root) {
  if (!root.is_object()) {
    throw ProfileError("machine profile: the top level must be an object");
  }
  Profile profile = defaultProfile();
  parseSeries(root, profile);
  // Axes first: work offsets are checked against the axis count.
  if (root.contains("axes")) {
    parseAxes(root["axes"], profile);
  }
  if (root.contains("tool_offsets")) {
    parseToolOffsets(root["tool_offsets"], profile);
  }
  for (const auto& [key, item] : root.items()) {
    if (key == "axes" || key == "tool_offsets" || key == "series") {
      continue;
    }
    if (key == "units") {
      parseUnits(item, profile);
    } else if (key == "rapid_rate") {
      profile.rapidRate = number(item, key);
      if (profile.rapidRate <= 0.0) {
        fail(key, "must be positive");
      }
    } else if (key == "parameters") {
      parseParameters(item, profile);
    } else if (key == "work_offsets") {
      parseWorkOffsets(item, profile);
    } else if (key == "variables") {
      parseVariables(item, profile);
    } else if (key == "extended_common") {
      profile.extendedCommon = boolean(item, key);
    } else if (key == "common_98000") {
      profile.commons98000 = boolean(item, key);
    } else if (key == "limits") {
      parseLimits(item, profile);
    } else if (key == "input_signals") {
      parseInputSignals(item, profile);
    } else if (key == "parts") {
      parseParts(item, profile);
    } else if (key == "program_number_digits") {
      if (item != 4 && item != 8) {
        fail(key, "must be 4 or 8");
      }
      profile.programNumberDigits = item.get<int>();
    } else if (key == "block_skip") {
      profile.blockSkip = boolean(item, key);
    } else if (key == "probe") {
      profile.probe = parseProbeScene(item);
    } else {
      unknownKey(key);
    }
  }
  profile.rotaryMask = rotaryAxes(profile);
  profile.diameterMask = diameterAxes(profile) & ~profile.rotaryMask;
  finishLathe(profile);
  for (int axis = 0; axis < static_cast<int>(profile.axes.size()); ++axis) {
    const auto bits = static_cast<long>(profile.axisParameter(1008, axis));
    const std::uint32_t bit = std::uint32_t{1} << axis;
    if ((bits & 1) != 0 && (profile.rotaryMask & bit) != 0) {
      profile.rolloverMask |= bit;
      profile.bySignMask |= (bits & 2) != 0 ? bit : 0;
      const double degrees = profile.axisParameter(1260, axis);
      profile.rotationDegrees[axis] = degrees > 0.0 ? degrees : 360.0;
    }
  }
  return profile;
}

} // namespace

double Profile::parameter(int number) const {
  if (const auto it = parameters.find(number); it != parameters.end()) {
    return it->second;
  }
  const ParameterSpec* spec = findParameter(number);
  return spec != nullptr ? spec->fallback : 0.0;
}

double Profile::axisParameter(int number, int axis) const {
  if (const auto it = axisParameters.find(number); it != axisParameters.end()) {
    return it->second[axis];
  }
  const ParameterSpec* spec = findParameter(number);
  return spec != nullptr ? spec->fallback : 0.0;
}

AxisValues& Profile::axisParameterValues(int number) {
  const auto [it, added] = axisParameters.try_emplace(number);
  if (added) {
    const ParameterSpec* spec = findParameter(number);
    it->second.fill(spec != nullptr ? spec->fallback : 0.0);
  }
  return it->second;
}

bool Profile::parameterBit(int number, int bit) const {
  return (static_cast<long>(parameter(number)) >> bit & 1) != 0;
}

Profile defaultProfile() {
  Profile profile;
  profile.toolOffsets.assign(profile.toolOffsetCount + 1, ToolOffset{});
  profile.workOffsets.assign(kWorkOffsetCount, AxisValues{});
  return profile;
}

std::optional<Profile> parseProfile(std::string_view text, std::string& error) {
  try {
    return parseTopLevel(json::parse(text));
  } catch (const ProfileError& e) {
    error = e.what();
  } catch (const json::exception& e) {
    error = std::string("machine profile: invalid JSON: ") + e.what();
  }
  return std::nullopt;
}

} // namespace mbc::rt
