// The G codes whose axis words are data, not a move: those that set
// coordinate frames (frames.h) and G10 (data_input.h):
// G52 local origin, G92 coordinate system setting and G92.1 preset,
// G51/G50 scaling,
// G51.1/G50.1 programmable mirror, G68/G69 rotation and G43/G44/G49 tool
// length offset. None of them moves, except a tool length change in a
// block without motion (motion.h moveToFrame).
#pragma once

#include <array>
#include <optional>

#include "context.h"
#include "motion.h"

namespace mbc::rt {

/// What a block says about frames.
struct FrameWords {
  int code = 0;                // 100 G10, 520 G52, 920 G92, 921 G92.1, 510 G51,
                               // 511 G51.1, 501 G50.1, 680 G68
  bool cancelScaling = false;  // G50
  bool cancelRotation = false; // G69
  int lengthCode = 0;          // 43, 44, 49
  bool hasH = false;           // an H word: a new tool length offset
  const MotionWords* axes = nullptr;
  const mbrt_word* words = nullptr; // the whole block
  std::size_t count = 0;

  /// The last word of `letter` in the block, or nullptr.
  const mbrt_word* word(char letter) const;
};

/// True for the G codes a FrameWords::code holds.
bool isFrameCode(int tenths);

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
