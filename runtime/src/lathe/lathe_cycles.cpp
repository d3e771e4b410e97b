// A lathe's single cycles (lathe_cycles.h). G90: rapid in X to the cut,
// feed to the end point (along the taper), feed back out in X, rapid back
// in Z. G92 the same with a thread (F the lead) and rapid returns. G94:
// rapid in Z to the face, feed in X to the end point, feed back out in Z,
// rapid back in X. The taper R is the cut's start less its end: a radius
// (G90, G92) or along Z (G94); the Series 10/11 format writes it as I
// (G90, G92) or K (G94).
//
// Under tool nose radius compensation (0i-TF manual, canned cycles and tool
// nose radius compensation) the vector is cancelled at the start point, the
// cycle's first move starts the offset, and its return to the start point
// cancels it. G90 and G94 offset the tool on the side of the cut whatever
// G41/G42 say; G92 cuts its thread uncompensated.
#include "lathe_cycles.h"

#include "cutter_comp.h"
#include "lathe_codes.h"
#include "lathe_settings.h"
#include "programmed_moves.h"

namespace mbc::rt {

namespace {

struct CyclePoints {
  AxisCounts start, cut, end, back;
  bool rapidBack; // the third move: G92 leaves the thread at rapid
};

/// G90 and G94 under compensation: G42 where the finished part lies left of
/// the cut's travel in the ZX plane, else G41. G90 cuts along Z, the part
/// lying beyond the cut in X; G94 cuts along X, the part lying beyond it in
/// Z.
int cutSide(const AxisCounts& start, const AxisCounts& end, int x, int z,
            bool facing) {
  const auto sign = [](Counts v) { return v < 0 ? -1 : 1; };
  const int sx = sign(end[x] - start[x]);
  const int sz = sign(end[z] - start[z]);
  const bool partLeft = facing ? -sx == sz : sx == sz;
  return partLeft ? 42 : 41;
}

} // namespace

AxisCounts cycleEndPoint(const mbrt_ctx& ctx, const MotionWords& words) {
  AxisCounts end = ctx.machine.program;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((words.axisMask >> axis & 1) != 0) {
      const bool incremental = ctx.machine.modal.incremental ||
                               (words.incrementalMask >> axis & 1) != 0;
      end[axis] = incremental ? ctx.machine.program[axis] + words.axis[axis]
                              : words.axis[axis];
    }
  }
  return end;
}

mbrt_status executeSingleCycle(mbrt_ctx& ctx, const MotionWords& words) {
  if (const mbrt_status status = cancelVectorHere(ctx)) {
    return status;
  }
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  SingleCycleData& data = ctx.machine.modal.singleCycle;
  const AxisCounts start = ctx.machine.program;
  const AxisCounts given = cycleEndPoint(ctx, words);
  if ((words.axisMask >> x & 1) != 0) {
    data.hasX = true;
    data.x = given[x];
  }
  if ((words.axisMask >> z & 1) != 0) {
    data.hasZ = true;
    data.z = given[z];
  }
  const int cycle = ctx.machine.modal.motion;
  // The Series 10/11 format (0001#1 FCV) writes the taper as I (G90, G92)
  // or K (G94).
  const int taperIndex = cycle == kFacingCycleMotion ? 2 : 0;
  if (seriesTenFormat(ctx) && (words.centerMask >> taperIndex & 1) != 0) {
    data.r = words.center[static_cast<std::size_t>(taperIndex)];
  } else if (words.hasR) {
    data.r = words.r;
  }
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

  const int programmed = ctx.machine.modal.compensation;
  const int side = programmed == 40 || cycle == kThreadCycleMotion
                       ? 40
                       : cutSide(start, end, x, z, cycle == kFacingCycleMotion);

  const struct {
    const AxisCounts* to;
    bool rapid;
    int compensation; // the return to the start point cancels
  } moves[] = {{&p.cut, true, side},
               {&p.end, false, side},
               {&p.back, p.rapidBack, side},
               {&p.start, true, 40}};

  ctx.run.cycleLabel = static_cast<int>(
      writtenLatheCode(ctx.profile.gCodeSystem, kLatheOwnCode + cycle * 10));
  mbrt_status status = 0;
  for (const auto& move : moves) {
    ctx.machine.modal.compensation = move.compensation;
    status = moveLine(ctx, *move.to, move.rapid);
    if (status != 0) {
      break;
    }
  }
  ctx.machine.modal.compensation = programmed;
  ctx.run.cycleLabel = 0;
  return status;
}

} // namespace mbc::rt
