// What a block says about frames (frame_codes.h): its frame code, the
// cancels and the tool length code, and the words they read.
#pragma once

#include <cstddef>

#include "context.h"
#include "motion_words.h"

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
  const mbrt_word* word(char letter) const {
    for (std::size_t i = count; i > 0; --i) {
      if (words[i - 1].letter == letter) {
        return &words[i - 1];
      }
    }
    return nullptr;
  }
};

} // namespace mbc::rt
