// Canned cycles (G73, G74, G76, G81-G89 with G98/G99): each hole expanded
// into the rapid and feed moves the control makes, every move marked with
// its cycle.
#pragma once

#include <optional>

#include "motion_words.h"

namespace mbc::rt {

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

/// The cycle mode changes (G80 and group 01 codes cancel): a new cycle
/// takes the drilling axis's position as its initial level.
void changeCycle(mbrt_ctx& ctx, int cycle);

/// Drills the block's holes when it has an axis word or R; a block without
/// only updates the drilling data.
mbrt_status executeCycleBlock(mbrt_ctx& ctx, const CycleWords& words);

} // namespace mbc::rt
