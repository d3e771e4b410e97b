// The machine's unit (the profile's "units") beside the unit in force
// (G20/G21). The offset memory keeps its work offsets in counts of the
// machine's unit, as a control's memory does, so that a switch to the other
// unit and back loses nothing and a state file saves them exactly; the
// program sees and writes them in the unit in force.
#pragma once

#include <mbc/arith.h>

#include "context.h"

namespace mbc::rt {

/// Counts of one unit in counts of the other: 0.0001 inch is 2.54 counts
/// of 0.001 mm.
inline double unitCountsFactor(bool toInch) {
  return toInch ? 1.0 / 2.54 : 2.54;
}

/// Counts of `axis` in the other unit, rounded to its increment; a rotary
/// axis counts 0.001 degree in both.
inline Counts toOtherUnit(const mbrt_ctx& ctx, int axis, Counts counts,
                          bool toInch) {
  if (ctx.isRotary(axis)) {
    return counts;
  }
  return static_cast<Counts>(
      roundHalfAway(static_cast<double>(counts) * unitCountsFactor(toInch)));
}

/// A work offset (an index of workOffsets) on `axis` in counts of the unit
/// in force.
inline Counts workOffsetInForce(const mbrt_ctx& ctx, int index, int axis) {
  const Counts stored = ctx.data.workOffsets[index][axis];
  return ctx.machine.modal.inch == ctx.profile.inch
             ? stored
             : toOtherUnit(ctx, axis, stored, ctx.machine.modal.inch);
}

/// Stores a work offset given in counts of the unit in force.
inline void storeWorkOffset(mbrt_ctx& ctx, int index, int axis, Counts counts) {
  ctx.data.workOffsets[index][axis] =
      ctx.machine.modal.inch == ctx.profile.inch
          ? counts
          : toOtherUnit(ctx, axis, counts, ctx.profile.inch);
}

} // namespace mbc::rt
