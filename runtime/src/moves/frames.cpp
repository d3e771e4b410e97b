// The transforms between program, workpiece and machine coordinates, in
// counts of the least increment. Mirror, scaling and rotation each keep
// their centre (a program point) in place; only these make positions that
// are not whole counts, and they are rounded half away from zero.
#include "frames.h"

#include <mbc/arith.h>

#include "machine_unit.h"

namespace mbc::rt {

namespace {

AxisValues toValues(const AxisCounts& counts) {
  AxisValues values{};
  for (std::size_t axis = 0; axis < counts.size(); ++axis) {
    values[axis] = static_cast<double>(counts[axis]);
  }
  return values;
}

AxisCounts toCounts(const AxisValues& values) {
  AxisCounts counts{};
  for (std::size_t axis = 0; axis < values.size(); ++axis) {
    counts[axis] = static_cast<Counts>(roundHalfAway(values[axis]));
  }
  return counts;
}

/// The workpiece coordinate of a program coordinate when no frame
/// transforms: the local origin added.
Counts unframedWork(const mbrt_ctx& ctx, const AxisCounts& program, int axis) {
  return program[axis] + ctx.machine.frames.local[axis];
}

/// What makes a workpiece coordinate of `axis` a machine coordinate: the
/// work offset, the external offset, the G92 shift, and the tool's offsets
/// (a lathe's geometry and wear, the tool length on its axis).
Counts machineShift(const mbrt_ctx& ctx, int axis) {
  const Frames& frames = ctx.machine.frames;
  return workOffsetInForce(ctx, ctx.machine.modal.workOffset, axis) +
         workOffsetInForce(ctx, kExternalOffset, axis) + frames.preset[axis] +
         frames.toolGeometry[axis] + frames.toolWear[axis] +
         (axis == frames.lengthAxis ? frames.length : 0);
}

/// Its own inverse.
void mirror(const Frames& frames, AxisValues& point) {
  for (std::size_t axis = 0; axis < point.size(); ++axis) {
    if ((frames.mirrorMask >> axis & 1) != 0) {
      point[axis] = 2.0 * frames.mirrorCenter[axis] - point[axis];
    }
  }
}

/// Rotation by the G68 angle; `sign` -1 turns back.
void rotate(const Frames& frames, AxisValues& point, double sign) {
  const int p = frames.rotationAxes[0];
  const int q = frames.rotationAxes[1];
  const double sine = sign * frames.sinAngle;
  const double dp = point[p] - frames.rotationCenter[0];
  const double dq = point[q] - frames.rotationCenter[1];
  point[p] = frames.rotationCenter[0] + frames.cosAngle * dp - sine * dq;
  point[q] = frames.rotationCenter[1] + sine * dp + frames.cosAngle * dq;
}

/// Scaling by the G51 factors; `power` -1 divides by them.
void scale(const Frames& frames, AxisValues& point, int power) {
  for (std::size_t axis = 0; axis < point.size(); ++axis) {
    const double factor =
        power > 0 ? frames.scale[axis] : 1.0 / frames.scale[axis];
    point[axis] = frames.scaleCenter[axis] +
                  (point[axis] - frames.scaleCenter[axis]) * factor;
  }
}

AxisValues untransformPoint(const Frames& frames, AxisValues point) {
  if (frames.rotation) {
    rotate(frames, point, -1.0);
  }
  if (frames.scaling) {
    scale(frames, point, -1);
  }
  mirror(frames, point);
  return point;
}

} // namespace

AxisValues transformPoint(const mbrt_ctx& ctx, AxisValues point) {
  const Frames& frames = ctx.machine.frames;
  mirror(frames, point);
  if (frames.scaling) {
    scale(frames, point, 1);
  }
  if (frames.rotation) {
    rotate(frames, point, 1.0);
  }
  return point;
}

namespace {

/// Whether `program` leaves `axis` where the last resync found the tool:
/// its coordinate is the same, and under rotation, when it is one of the
/// rotated pair, its partner's too.
bool staysSynced(const Frames& frames, const AxisCounts& program, int axis) {
  const auto same = [&](int a) {
    return program[a] == frames.syncedProgram[a];
  };
  if (!same(axis)) {
    return false;
  }
  const int p = frames.rotationAxes[0];
  const int q = frames.rotationAxes[1];
  return !frames.rotation || (axis != p && axis != q) || (same(p) && same(q));
}

} // namespace

AxisCounts programToWork(const mbrt_ctx& ctx, const AxisCounts& program) {
  const Frames& frames = ctx.machine.frames;
  if (!frames.transforms()) {
    AxisCounts work = program;
    for (int axis = 0; axis < ctx.axisCount(); ++axis) {
      work[axis] = unframedWork(ctx, program, axis);
    }
    return work;
  }
  AxisCounts work = toCounts(transformPoint(ctx, toValues(program)));
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    work[axis] = frames.synced && staysSynced(frames, program, axis)
                     ? frames.syncedWork[axis]
                     : work[axis] + frames.local[axis];
  }
  return work;
}

AxisCounts workToMachine(const mbrt_ctx& ctx, const AxisCounts& work) {
  AxisCounts machine{};
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    machine[axis] = work[axis] + machineShift(ctx, axis);
  }
  return machine;
}

void placeProgramPoint(const mbrt_ctx& ctx, const AxisCounts& program,
                       AxisCounts& work, AxisCounts& machine) {
  if (ctx.machine.frames.transforms()) {
    work = programToWork(ctx, program);
    machine = workToMachine(ctx, work);
    return;
  }
  const int count = ctx.axisCount();
  for (int axis = 0; axis < MBRT_MAX_AXES; ++axis) {
    const bool used = axis < count;
    work[axis] = used ? unframedWork(ctx, program, axis) : program[axis];
    machine[axis] = used ? work[axis] + machineShift(ctx, axis) : 0;
  }
}

AxisCounts machineToWork(const mbrt_ctx& ctx, const AxisCounts& machine) {
  AxisCounts work{};
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    work[axis] = machine[axis] - machineShift(ctx, axis);
  }
  return work;
}

namespace {

/// The control point in local coordinates without the tool length offset.
AxisCounts localTip(const mbrt_ctx& ctx) {
  AxisCounts local = machineToWork(ctx, ctx.machine.position);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    local[axis] -= ctx.machine.frames.local[axis];
  }
  return local;
}

} // namespace

AxisCounts localPosition(const mbrt_ctx& ctx) {
  AxisCounts local = localTip(ctx);
  if (ctx.machine.frames.lengthAxis >= 0) {
    local[ctx.machine.frames.lengthAxis] += ctx.machine.frames.length;
  }
  return local;
}

void resyncProgram(mbrt_ctx& ctx) {
  const AxisCounts local = localTip(ctx);
  Frames& frames = ctx.machine.frames;
  frames.synced = frames.transforms();
  if (!frames.synced) {
    ctx.machine.program = local;
    return;
  }
  ctx.machine.program = toCounts(untransformPoint(frames, toValues(local)));
  frames.syncedProgram = ctx.machine.program;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    frames.syncedWork[axis] = local[axis] + frames.local[axis];
  }
}

Placement placementOf(const mbrt_ctx& ctx) {
  return {ctx.machine.frames,
          ctx.data.workOffsets[ctx.machine.modal.workOffset],
          ctx.data.workOffsets[kExternalOffset]};
}

PlacedAs::PlacedAs(mbrt_ctx& ctx, const Placement& placement)
    : ctx_(ctx), own_(placementOf(ctx)),
      workOffset_(ctx.machine.modal.workOffset) {
  ctx.machine.frames = placement.frames;
  ctx.data.workOffsets[workOffset_] = placement.workOffset;
  ctx.data.workOffsets[kExternalOffset] = placement.external;
}

PlacedAs::~PlacedAs() {
  ctx_.machine.frames = own_.frames;
  ctx_.data.workOffsets[kExternalOffset] = own_.external;
  ctx_.data.workOffsets[workOffset_] = own_.workOffset;
}

ArcFrame arcFrame(const mbrt_ctx& ctx, int firstAxis, int secondAxis) {
  const Frames& frames = ctx.machine.frames;
  ArcFrame arc;
  const auto mirrored = [&](int axis) {
    return (frames.mirrorMask >> axis & 1) != 0;
  };
  arc.reversed = mirrored(firstAxis) != mirrored(secondAxis);
  if (frames.scaling) {
    const double first = frames.scale[firstAxis];
    const double second = frames.scale[secondAxis];
    arc.supported = std::fabs(first) == std::fabs(second);
    arc.reversed = arc.reversed != ((first < 0) != (second < 0));
    arc.scale = std::fabs(first);
  }
  if (frames.rotation) {
    const bool samePlane = (frames.rotationAxes[0] == firstAxis &&
                            frames.rotationAxes[1] == secondAxis);
    arc.supported = arc.supported && samePlane;
  }
  return arc;
}

} // namespace mbc::rt
