// The settings of a lathe's multiple repetitive cycles (parameters
// 5130-5143): a cycle's first block overwrites them until power-off
// (mbrt_ctx::cycleSettings, lengths in mm), else the profile's parameter.
#pragma once

#include <mbc/arith.h>

#include "context.h"
#include "lathe_state.h"

namespace mbc::rt {

inline double cycleSetting(const mbrt_ctx& ctx, int parameter) {
  const auto it = ctx.lathe->cycleSettings.find(parameter);
  return it != ctx.lathe->cycleSettings.end()
             ? it->second
             : ctx.profile.parameter(parameter);
}

/// A length setting in counts.
inline Counts cycleLength(const mbrt_ctx& ctx, int parameter) {
  return static_cast<Counts>(
      roundHalfAway(cycleSetting(ctx, parameter) * ctx.countsPerMm()));
}

/// Parameter 0001#1 FCV: the program is in the Series 10/11 tape format,
/// whose G76 is one block (lathe_repetitive.h).
inline bool seriesTenFormat(const mbrt_ctx& ctx) {
  return ctx.profile.lathe() && ctx.profile.parameterBit(1, 1);
}

/// A word of the Series 10/11 format's one-block cycles that counts least
/// increments (D), in counts.
inline Counts incrementCounts(const mbrt_ctx& ctx, double increments) {
  return static_cast<Counts>(roundHalfAway(increments)) *
         ctx.countsPerIncrement();
}

inline void keepCycleLength(mbrt_ctx& ctx, int parameter, Counts counts) {
  ctx.lathe->cycleSettings[parameter] =
      static_cast<double>(counts) / ctx.countsPerMm();
}

} // namespace mbc::rt
