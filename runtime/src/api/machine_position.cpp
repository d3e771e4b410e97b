// Where the tool stands between runs, in the machine's unit (runtime.h,
// "The machine position"): a simulation starts a cycle from where its own
// model left the tool, as an operator jogs the machine before cycle start.
#include <mbc/runtime.h>

#include <cmath>

#include "context.h"
#include "frames.h"

using namespace mbc::rt;

int mbrt_get_stroke(const mbrt_ctx* ctx, int axis, double* low, double* high) {
  if (axis < 0 || axis >= ctx->axisCount() ||
      (ctx->profile.strokeAxes() >> axis & 1) == 0) {
    return 0;
  }
  const auto i = static_cast<std::size_t>(axis);
  *low = ctx->profile.strokeLow[i];
  *high = ctx->profile.strokeHigh[i];
  return 1;
}

int mbrt_get_machine_position(const mbrt_ctx* ctx, int axis, double* value) {
  if (axis < 0 || axis >= ctx->axisCount()) {
    return 0;
  }
  *value = countsToUnits(ctx->machine.position[axis],
                         ctx->axisScale(axis, ctx->profile.inch));
  return 1;
}

int mbrt_set_machine_position(mbrt_ctx* ctx, int axis, double value) {
  if (axis < 0 || axis >= ctx->axisCount() || !std::isfinite(value) ||
      refuseInSink(*ctx, "mbrt_set_machine_position")) {
    return 0;
  }
  const int per = ctx->axisCountsPerIncrement(axis);
  const double counts =
      roundToCounts(value, ctx->axisIncrements(axis, ctx->profile.inch));
  if (!fitsAddress(counts)) {
    return 0;
  }
  ctx->machine.position[axis] = static_cast<Counts>(counts) * per;
  resyncProgram(*ctx); // the work coordinates follow the machine
  return 1;
}
