// The FANUC parameters a machine profile may set: their numbers, ranges and
// defaults (docs/machine-profile.md lists their meaning).
#pragma once

#include <span>

namespace mbc::rt {

struct ParameterSpec {
  int first; // a run of numbers with the same range: 6050..6059
  int last;
  double low;
  double high;
  double fallback;      // the value of a parameter the profile does not set
  bool whole;           // bit parameters and codes take whole numbers
  bool perAxis = false; // one value per axis: a JSON array in the profile

  /// A bit parameter: its value is the byte of bits 0-7.
  bool bits() const { return whole && high == 255.0; }
};

/// The spec of parameter `number`, or nullptr when profiles cannot set it.
const ParameterSpec* findParameter(int number);

/// Every spec (docs/machine-profile.md lists them, checked by a test).
std::span<const ParameterSpec> parameterSpecs();

} // namespace mbc::rt
