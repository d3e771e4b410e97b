// Programmable parameter input: G10 L52 (L50 in some manuals) starts a mode
// in which each block sets one parameter, `N<number> R<value>`, with
// P<axis> for a per-axis parameter and Q<bit> for one bit of a bit
// parameter, until G11.
#pragma once

#include "frame_words.h"

namespace mbc::rt {

/// Whether a G10 block's L starts the parameter input mode.
bool startsParameterInput(const FrameWords& words);

/// The G10 L52 block: the blocks that follow set parameters.
mbrt_status startParameterInput(mbrt_ctx& ctx, const FrameWords& words);

/// A block in the parameter input mode (mbrt_ctx::parameterInput): G11 ends
/// the mode, any other block sets the parameter its N names.
mbrt_status parameterInputBlock(mbrt_ctx& ctx, const mbrt_word* words,
                                size_t count);

} // namespace mbc::rt
