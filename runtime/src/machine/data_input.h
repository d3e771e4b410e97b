// G10 programmable data input: work offsets (L2 external and G54-G59, L20
// G54.1) and tool offsets (L10-L13, memory C), set in G90, added in G91.
#pragma once

#include "frame_words.h"

namespace mbc::rt {

/// Executes a G10 block; its axis words and R are the data.
mbrt_status programmableDataInput(mbrt_ctx& ctx, const FrameWords& words);

} // namespace mbc::rt
