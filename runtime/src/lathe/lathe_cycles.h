// A lathe's single cycles (group 01, modal): G90 outer/inner diameter
// cutting, G92 threading and G94 end face cutting (system A; B: G77-G79,
// C: G20, G21, G24). Each block with axis words runs four moves from the
// start point A and back to it; X(U), Z(W) and the taper R stay in force
// for the next block, so that a block with X alone cuts the next pass.
#pragma once

#include "motion_words.h"

namespace mbc::rt {

/// A cycle block's end point: its X(U), Z(W)... from the program
/// position, which stays on the axes it leaves out.
AxisCounts cycleEndPoint(const mbrt_ctx& ctx, const MotionWords& words);

/// One cycle of the single cycle in force (ctx.machine.modal.motion).
mbrt_status executeSingleCycle(mbrt_ctx& ctx, const MotionWords& words);

} // namespace mbc::rt
