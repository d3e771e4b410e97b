// Canned cycles (G73, G74, G76, G81-G89 with G98/G99): each hole expanded
// into the rapid and feed moves the control makes, every move marked with
// its cycle.
#pragma once

#include "motion_words.h"

namespace mbc::rt {

/// The cycle mode changes (G80 and group 01 codes cancel): a new cycle
/// takes the drilling axis's position as its initial level.
void changeCycle(mbrt_ctx& ctx, int cycle);

/// Drills the block's holes when it has an axis word or R; a block without
/// only updates the drilling data.
mbrt_status executeCycleBlock(mbrt_ctx& ctx, const CycleWords& words);

} // namespace mbc::rt
