// The motion of an NC block (motion.h): a chamfer or corner R it holds or
// ends, a single cycle it starts, or its programmed move.
#include "motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "corner_blends.h"
#include "corner_state.h"
#include "lathe_codes.h"
#include "lathe_corners.h"
#include "lathe_cycles.h"
#include "programmed_moves.h"

namespace mbc::rt {

namespace {

/// G34's K (a length per revolution) into ctx.machine.leadChange; PS0014 when
/// the lead would shrink to nothing before the thread's end.
mbrt_status readLeadChange(mbrt_ctx& ctx, const MotionWords& words,
                           const AxisCounts& target) {
  const bool hasK = (words.centerMask >> 2 & 1) != 0;
  ctx.machine.leadChange =
      hasK ? static_cast<double>(words.center[2]) / ctx.scale() : 0.0;
  double longest = 0.0; // the thread's length along its longer axis
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (!ctx.isRotary(axis)) {
      longest =
          std::max(longest, std::fabs(static_cast<double>(
                                target[axis] - ctx.machine.program[axis])) /
                                ctx.scale());
    }
  }
  const double lead = ctx.machine.modal.feed;
  if (lead * lead + 2.0 * ctx.machine.leadChange * longest <= 0.0) {
    return raise(ctx, AlarmId::IllegalLeadCommand,
                 fmt::format("G34 F{} K{}: the lead shrinks to 0 before the "
                             "thread's end, {} long",
                             lead, ctx.machine.leadChange, longest));
  }
  return 0;
}

} // namespace

mbrt_status executeMotion(mbrt_ctx& ctx, const MotionWords& words) {
  const int mode = ctx.machine.modal.motion;
  const AxisCounts start = ctx.machine.program;
  AxisCounts target = workTarget(ctx, words, start);
  if (words.angle && !(ctx.corner->pending && ctx.corner->openEnd)) {
    if (const mbrt_status status = endAngledLine(ctx, words, start, target)) {
      return status;
    }
  }
  if (ctx.corner->pending) {
    return moveAfterCorner(ctx, words, target);
  }
  if (hasCommaWords(words) && holdsForNextBlock(ctx, words)) {
    return holdBlendMove(ctx, words, start, target);
  }
  if (mode == 1 && ctx.profile.lathe() && insertsCorner(ctx, words)) {
    return holdCornerMove(ctx, words, start, target);
  }
  if (mode == kVariableLeadMotion) {
    if (const mbrt_status status = readLeadChange(ctx, words, target)) {
      return status;
    }
  }
  if (mode == 0 || mode == 1 || mode == kThreadingMotion ||
      mode == kVariableLeadMotion) {
    return moveLine(ctx, target, mode == 0, &words);
  }
  if (isSingleCycle(mode)) {
    return executeSingleCycle(ctx, words);
  }
  return moveArc(ctx, words, start, target);
}

} // namespace mbc::rt
