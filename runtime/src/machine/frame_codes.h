// The G codes whose axis words are data, not a move: those that set
// coordinate frames (frames.h) and G10 (data_input.h):
// G52 local origin, G92 coordinate system setting and G92.1 preset,
// G51/G50 scaling,
// G51.1/G50.1 programmable mirror, G68/G69 rotation and G43/G44/G49 tool
// length offset. None of them moves, except a tool length change in a
// block without motion (programmed_moves.h moveToFrame).
#pragma once

#include <array>
#include <optional>

#include "context.h"
#include "frame_words.h"

namespace mbc::rt {

/// executeFrameCodes for a block that has any frame words.
mbrt_status applyFrameCodes(mbrt_ctx& ctx, const FrameWords& words,
                            bool* lengthChanged);

/// Applies the block's frame codes; `lengthChanged` tells that the tool
/// length offset changed, so that a block without motion moves by it.
/// Inline because most blocks have none, and the test is cheaper than the
/// call.
inline mbrt_status executeFrameCodes(mbrt_ctx& ctx, const FrameWords& words,
                                     bool* lengthChanged) {
  *lengthChanged = false;
  if (words.code == 0 && !words.cancelScaling && !words.cancelRotation &&
      words.lengthCode == 0 && !words.hasH) {
    return 0;
  }
  return applyFrameCodes(ctx, words, lengthChanged);
}

} // namespace mbc::rt
