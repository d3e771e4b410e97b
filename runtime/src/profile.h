// The machine profile: what a context knows about the machine it simulates
// (axes, units, parameters, offsets, limits). Parsed from the JSON format of
// docs/machine-profile.md; an empty text gives the built-in default.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mbc::rt {

/// Axis letters a profile may name.
inline constexpr std::string_view kAxisLetters = "XYZABCUVW";
/// Work coordinate systems: external, G54..G59, G54.1 P1..P300.
inline constexpr int kExternalOffset = 0;
inline constexpr int kFirstG54Offset = 1;
inline constexpr int kFirstG541Offset = 7;
inline constexpr int kG541Count = 300;
inline constexpr int kWorkOffsetCount = kFirstG541Offset + kG541Count;
inline constexpr int kMaxToolOffsets = 999;

struct ToolOffset {
  double hGeometry = 0.0;
  double hWear = 0.0;
  double dGeometry = 0.0;
  double dWear = 0.0;
};

using AxisValues = std::array<double, MBRT_MAX_AXES>;

struct Profile {
  std::string axes = "XYZ";
  bool inch = false;
  double rapidRate = 10000.0; // mm/min
  // Raw parameter values as the profile gives them; the bits below are read
  // from them.
  int param3401 = 0;
  int param6001 = 0;
  int param6004 = 0;
  double param3410 = 0.02; // arc radius tolerance in mm, 0 = no check
  int toolOffsetCount = 400;
  std::vector<ToolOffset> toolOffsets;           // index 0 unused
  std::vector<AxisValues> workOffsets;           // kWorkOffsetCount entries
  std::vector<std::pair<int, double>> variables; // #500..#999 start values
  bool extendedCommon = false;
  int macroNesting = 5;
  int subprogramNesting = 10;
  int totalNesting = 15;
  double partsCount = 0.0;
  double partsRequired = 0.0;
  bool blockSkip = false;

  /// 3401#0 DPI: literals without decimal point are whole units.
  bool decimalPointInput() const { return (param3401 & 1) != 0; }

  /// 6001#1 PRT: DPRNT drops leading zeros and the plus sign.
  bool prt() const { return (param6001 & 2) != 0; }

  /// 6004#0 NAT: ASIN/ATAN in -90..90 / -180..180.
  bool nat() const { return (param6004 & 1) != 0; }
};

/// The built-in 3-axis metric vertical mill.
Profile defaultProfile();

/// Parses profile JSON; on error returns nullopt and sets `error` to a
/// message naming the offending key.
std::optional<Profile> parseProfile(std::string_view text, std::string& error);

} // namespace mbc::rt
