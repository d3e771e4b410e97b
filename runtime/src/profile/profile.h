// The machine profile: what a context knows about the machine it simulates
// (axes, units, parameters, offsets, limits). Parsed from the JSON format of
// docs/machine-profile.md; an empty text gives the built-in default.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "probe_scene.h"

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

/// A lathe's offset: X (a diameter on a diameter axis), Z and Y position
/// offsets, the tool nose radius R and the imaginary tip direction T (0-9).
struct LatheOffset {
  double xGeometry = 0.0;
  double xWear = 0.0;
  double zGeometry = 0.0;
  double zWear = 0.0;
  double yGeometry = 0.0;
  double yWear = 0.0;
  double rGeometry = 0.0;
  double rWear = 0.0;
  double tip = 0.0;
};

inline constexpr int kDefaultLatheOffsets = 64;

using AxisValues = std::array<double, MBRT_MAX_AXES>;

/// FANUC's two series: M (machining centres) and T (lathes).
enum class Series : char { Mill = 'M', Lathe = 'T' };

struct Profile {
  Series series = Series::Mill;
  // The lathe's G code system A, B or C (3401#6 GSB, #7 GSC).
  char gCodeSystem = 'A';
  std::string axes = "XYZ";
  // Bit n: axis n is programmed as a diameter (1006#3 DIA; by default X on
  // a lathe).
  std::uint32_t diameterMask = 0;
  // Bit n: axis n is rotary (1006#0 ROT; by default A, B and C): degrees,
  // 0.001 degree whatever G20/G21.
  std::uint32_t rotaryMask = 0;
  // Bit n: rotary axis n rolls over (1008#0 ROA), its positions kept within
  // one rotation (1260, 360 degrees unless set), and goes the way of the
  // command's sign rather than the shorter way (1008#1 RAB, bySignMask).
  std::uint32_t rolloverMask = 0;
  std::uint32_t bySignMask = 0;
  AxisValues rotationDegrees{}; // one rotation of each axis that rolls over
  bool inch = false;
  double rapidRate = 10000.0; // mm/min
  // The parameters the profile sets (parameters.h has the others' defaults).
  std::map<int, double> parameters;
  std::map<int, AxisValues> axisParameters; // 1241: one value per axis
  // Stored stroke check 1 (1320/1321, derived): bit n, axis n has a stroke,
  // strokeLow[n]..strokeHigh[n] in machine coordinates, mm (a diameter axis
  // in diameter) or degrees.
  std::uint32_t strokeMask = 0;
  AxisValues strokeLow{};
  AxisValues strokeHigh{};
  int toolOffsetCount = 400;
  char toolOffsetMemory = 'C';         // offset memory type A, B or C
  std::vector<ToolOffset> toolOffsets; // index 0 unused
  // A lathe's offsets instead (index 0 unused), geometry and wear apart
  // unless `geometryWear` is false (one value, in the wear fields).
  std::vector<LatheOffset> latheOffsets;
  bool geometryWear = true;
  std::vector<AxisValues> workOffsets;              // kWorkOffsetCount entries
  std::vector<std::pair<int, double>> variables;    // #500..#999 start values
  std::vector<std::pair<int, double>> inputSignals; // #1000..#1035
  bool extendedCommon = false;
  bool commons98000 = false; // #98000-#98499
  int macroNesting = 5;
  int subprogramNesting = 10;
  int totalNesting = 15;
  double partsCount = 0.0;
  double partsRequired = 0.0;
  bool blockSkip = false;
  // 8: O1-O99999999, M98 P is the program number alone (8-digit program
  // number option); 4: O1-O9999, M98 P may carry the repeat count.
  int programNumberDigits = 8;
  ProbeScene probe; // what G31 touches

  // Bits read on every NC word or function call, kept out of the map.
  bool decimalPointInput = false; // 3401#0 DPI: X10 is 10 mm, not 0.010
  bool prt = false; // 6001#1 PRT: DPRNT drops leading zeros and the sign
  bool nat = false; // 6004#0 NAT: ASIN/ATAN in -90..90 / -180..180
  bool v15 = false; // 6000#3 V15: tool offset variables as on a Series 15
  bool clearOnReset = false;    // 3402#6 CLR: a run starts from the clear state
  double rigidTappingCode = 29; // 5210: the M code of rigid tapping
  // Some G, M, T, S or B code calls a program (6001#5, 6007#4/#5,
  // 6050-6089): without, NC blocks skip looking for code calls.
  bool codeCalls = false;

  /// The value of a parameter, its default when the profile does not set
  /// it, 0 for a parameter mbc does not model.
  double parameter(int number) const;
  bool parameterBit(int number, int bit) const;

  bool lathe() const { return series == Series::Lathe; }

  /// The axes the stored stroke check holds: those with a stroke that do
  /// not roll over (a position within one turn has no end to pass).
  std::uint32_t strokeAxes() const { return strokeMask & ~rolloverMask; }

  /// A per-axis parameter's value for `axis`, its unset value (parameters.h)
  /// when the profile does not set it.
  double axisParameter(int number, int axis) const;

  /// The values of per-axis parameter `number`, every axis at its unset
  /// value until the profile or a program sets it.
  AxisValues& axisParameterValues(int number);
};

struct ParameterSpec;

/// What is wrong with `x` as the value of a parameter of `spec` ("must be
/// a whole number from 0 to 255"), or nothing.
std::optional<std::string> parameterValueError(const ParameterSpec& spec,
                                               double x);

/// What is wrong with `x` as parameter n when n makes a code call (6050-
/// 6089), or nothing.
std::optional<std::string> callingCodeError(int n, double x);

/// The fields kept apart from the parameters (decimalPointInput, nat...),
/// again from the parameters: after the profile is read, and after a
/// program sets a parameter (G10 L52).
void deriveParameterFields(Profile& profile);

/// The built-in 3-axis metric vertical mill.
Profile defaultProfile();

/// Parses profile JSON; on error returns nullopt and sets `error` to a
/// message naming the offending key.
std::optional<Profile> parseProfile(std::string_view text, std::string& error);

} // namespace mbc::rt
