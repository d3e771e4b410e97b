// Coordinate frames (spec §6.5, docs/language.md "Coordinates"): a point a
// program commands goes through the programmable mirror (G51.1), scaling
// (G51) and rotation (G68) into the workpiece frame, where the G52 local
// origin is added; the work offset, the external offset and the G92 shift
// make it a machine position, and the tool length offset (G43/G44) moves
// the control point. The machine position is the truth; the program
// position is kept beside it so that rotated and scaled moves do not drift.
#pragma once

#include "context.h"
#include "move_state.h"

namespace mbc::rt {

/// A program point through mirror, scaling and rotation, unrounded; the
/// local origin is not added.
AxisValues transformPoint(const mbrt_ctx& ctx, AxisValues point);

/// A program position in the workpiece frame (local origin added).
AxisCounts programToWork(const mbrt_ctx& ctx, const AxisCounts& program);

/// A workpiece-frame position as the control point's machine position.
AxisCounts workToMachine(const mbrt_ctx& ctx, const AxisCounts& work);

/// A program position in the workpiece frame (`work`) and as the control
/// point's machine position (`machine`): programToWork, then
/// workToMachine. Every straight move asks: without a frame it takes one
/// pass over the axes, and it writes where the caller keeps the points. A
/// result returned would be built aside and copied, and the copy's wide
/// loads wait for the narrow stores before them (store forwarding).
void placeProgramPoint(const mbrt_ctx& ctx, const AxisCounts& program,
                       AxisCounts& work, AxisCounts& machine);

/// The workpiece-frame position of a machine position.
AxisCounts machineToWork(const mbrt_ctx& ctx, const AxisCounts& machine);

/// The control point in local coordinates (after mirror, scaling and
/// rotation), the tool length offset in it: #5041, and #5061 at a skip.
AxisCounts localPosition(const mbrt_ctx& ctx);

/// After a frame or offset changed under a standing machine: the program
/// position that now names the control point.
void resyncProgram(mbrt_ctx& ctx);

/// The placement in force (context.h).
Placement placementOf(const mbrt_ctx& ctx);

/// While it lives, the context places points as `placement` does, with the
/// work offset its modal state selects: a held move leaves in the placement
/// of its own block. The context's own comes back after.
class PlacedAs {
public:
  PlacedAs(mbrt_ctx& ctx, const Placement& placement);
  ~PlacedAs();
  PlacedAs(const PlacedAs&) = delete;
  PlacedAs& operator=(const PlacedAs&) = delete;

private:
  mbrt_ctx& ctx_;
  Placement own_;
  int workOffset_;
};

/// How an arc in `plane` looks in the workpiece frame: its radius is
/// multiplied by `scale` and, when `reversed`, it turns the other way.
/// `supported` is false when mirror, scaling or rotation would make it an
/// ellipse or move it out of its plane.
struct ArcFrame {
  bool supported = true;
  bool reversed = false;
  double scale = 1.0;
};

ArcFrame arcFrame(const mbrt_ctx& ctx, int firstAxis, int secondAxis);

} // namespace mbc::rt
