// The motion of an NC block: its programmed move, or the chamfer, corner R
// or single cycle it starts or ends, handed on to the stages below
// (corner_blends.h, lathe_corners.h, lathe_cycles.h, programmed_moves.h).
#pragma once

#include "context.h"
#include "motion_words.h"

namespace mbc::rt {

/// Moves in the modal motion mode (G00..G03) to the block's end point.
mbrt_status executeMotion(mbrt_ctx& ctx, const MotionWords& words);

} // namespace mbc::rt
