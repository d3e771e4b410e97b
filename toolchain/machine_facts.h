// What mbc check knows of the machine a profile describes (--machine),
// read through the runtime's C API: the facts the analysis of where the
// tool goes (reach_box.h) needs, in the profile's unit.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mbc::toolchain {

/// One end to the other of an axis's stored stroke (1320/1321).
struct Stroke {
  double low = 0;
  double high = 0;
};

struct MachineFacts {
  std::string axes; // profile order: "XYZ"
  bool inch = false;
  bool lathe = false;
  bool decimalPointInput = false;   // 3401#0 DPI
  bool lengthOnPlaneNormal = false; // 5001#1 TLB
  // Some G, M, T, S or B code calls a program (6001#5, 6007, 6050-6089).
  bool codeCalls = false;
  std::vector<std::optional<Stroke>> strokes; // per axis
  std::uint32_t rotaryMask = 0;
  // G54-G59 (index 1-6) with the external offset in each, per axis.
  std::array<std::vector<double>, 7> workOffsets;
  std::vector<double> lengths; // H n: geometry + wear (index 0: none)
  double largestRadius = 0;    // of cutter compensation, any D
  std::array<std::vector<double>, 3> references; // G30 P2-P4 (1241-1243)
  std::vector<double> position; // where a run starts, machine coordinates

  int axisOf(char letter) const {
    const auto at = axes.find(letter);
    return at == std::string::npos ? -1 : static_cast<int>(at);
  }
};

/// The facts of the machine `ctx` was created for, before any run.
MachineFacts machineFacts(mbrt_ctx* ctx);

} // namespace mbc::toolchain
