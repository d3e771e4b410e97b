// The words of one block that define its motion, in counts, and a cycle
// block's drilling words: what the block's decoding hands the motion stages
// and the cycles (motion.h, programmed_moves.h, canned_cycles.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "context.h"

namespace mbc::rt {

/// The words of one block that define its motion, in counts.
struct MotionWords {
  std::uint32_t axisMask = 0; // bit a: axis a was written
  AxisCounts axis{};          // as written (absolute or incremental)
  // Bit a: axis a was written with its incremental address (a lathe's U
  // for X, W for Z), whatever G90/G91 says.
  std::uint32_t incrementalMask = 0;
  std::uint32_t centerMask = 0; // bit 0: I, 1: J, 2: K
  std::array<Counts, 3> center{};
  bool hasR = false;
  Counts r = 0;
  // A lathe's chamfer amount C, when 3405#4 CCR gives C for I and K.
  bool hasC = false;
  Counts c = 0;
  // ,C or ,R (corner_blends.h): 'C' or 'R' and its amount; 0 for none.
  char blend = 0;
  Counts blendAmount = 0;
  // ,A: the angle of the line from the plane's first axis, in degrees.
  std::optional<double> angle;
};

/// A block in canned cycle mode: its positioning and drilling words.
struct CycleWords {
  const MotionWords* motion; // axis words; R is the R level
  std::optional<Counts> q;
  std::optional<double> p; // dwell, ms
  std::optional<double> k; // repeat count (K, or L)
  // A lathe's G76 in the Series 10/11 format (lathe_repetitive.h): A the
  // tool angle, D the first depth (increments).
  std::optional<double> a;
  std::optional<double> d;
};

} // namespace mbc::rt
