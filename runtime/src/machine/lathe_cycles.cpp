// A lathe's single cycles (lathe_cycles.h). G90: rapid in X to the cut,
// feed to the end point (along the taper), feed back out in X, rapid back
// in Z. G92 the same with a thread (F the lead) and rapid returns. G94:
// rapid in Z to the face, feed in X to the end point, feed back out in Z,
// rapid back in X. The taper R is the cut's start less its end: a radius
// (G90, G92) or along Z (G94).
#include "lathe_cycles.h"

#include <fmt/format.h>

#include "cutter_comp.h"
#include "lathe_codes.h"

namespace mbc::rt {

namespace {

struct CyclePoints {
  AxisCounts start, cut, end, back;
  bool rapidBack; // the third move: G92 leaves the thread at rapid
};

} // namespace

AxisCounts cycleEndPoint(const mbrt_ctx& ctx, const MotionWords& words) {
  AxisCounts end = ctx.program;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((words.axisMask >> axis & 1) != 0) {
      const bool incremental =
          ctx.modal.incremental || (words.incrementalMask >> axis & 1) != 0;
      end[axis] =
          incremental ? ctx.program[axis] + words.axis[axis] : words.axis[axis];
    }
  }
  return end;
}

mbrt_status executeSingleCycle(mbrt_ctx& ctx, const MotionWords& words) {
  if (compensating(ctx)) { // FANUC compensates the cycle; mbc does not yet
    return refuseUnderCompensation(
        ctx, fmt::format(
                 "G{} under tool nose radius compensation",
                 writtenLatheCode(ctx, kLatheOwnCode + ctx.modal.motion * 10)));
  }
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  SingleCycleData& data = ctx.modal.singleCycle;
  const AxisCounts start = ctx.program;
  const AxisCounts given = cycleEndPoint(ctx, words);
  if ((words.axisMask >> x & 1) != 0) {
    data.hasX = true;
    data.x = given[x];
  }
  if ((words.axisMask >> z & 1) != 0) {
    data.hasZ = true;
    data.z = given[z];
  }
  if (words.hasR) {
    data.r = words.r;
  }
  const int cycle = ctx.modal.motion;
  AxisCounts end = start;
  end[x] = data.hasX ? data.x : start[x];
  end[z] = data.hasZ ? data.z : start[z];
  CyclePoints p{start, start, end, end, cycle == kThreadCycleMotion};
  if (cycle == kFacingCycleMotion) {
    p.cut[z] = end[z] + data.r;
    p.back[x] = end[x];
    p.back[z] = start[z];
  } else {
    p.cut[x] = end[x] + data.r;
    p.back[x] = start[x];
    p.back[z] = end[z];
  }

  const struct {
    const AxisCounts* to;
    bool rapid;
  } moves[] = {{&p.cut, true},
               {&p.end, false},
               {&p.back, p.rapidBack},
               {&p.start, true}};

  const int label =
      static_cast<int>(writtenLatheCode(ctx, kLatheOwnCode + cycle * 10));
  for (const auto& move : moves) {
    if (const mbrt_status status =
            moveStraight(ctx, *move.to, move.rapid, label)) {
      return status;
    }
  }
  return 0;
}

} // namespace mbc::rt
