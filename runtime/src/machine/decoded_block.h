// One NC block's words after conversion: what the G code handlers
// (g_code_handlers.h) and the rest of the block's execution (nc_block.cpp)
// hand each other.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "block_calls.h"
#include "context.h"
#include "frame_words.h"
#include "g_codes.h"
#include "motion_words.h"

namespace mbc::rt {

/// Which G codes a block holds: most hold none, or only codes that set one
/// modal field (setsOneField).
enum class GCodes { None, OneField, Other };

inline constexpr int kMaxOneFieldCodes = 4;

/// The words of one block after conversion.
struct NcBlock {
  GCodes gCodes = GCodes::None;
  // Under GCodes::OneField, the codes' rows (g_codes.def), in block order.
  std::array<std::uint8_t, kMaxOneFieldCodes> oneField{};
  int oneFieldCount = 0;
  MotionWords motion;
  bool hasP = false;
  // The first of P and L written with a decimal point (PS0007 but in
  // G51), or nullptr.
  const mbrt_word* countWithPoint = nullptr;
  bool hasL = false;
  double p = 0.0;
  double l = 0.0;
  std::optional<Counts> q;
  std::optional<double> qWritten; // Q as written: G05.1's switch
  // Q as a lathe cycle reads it: increments unless written with a decimal
  // point (a value from a variable counts increments, as P does).
  std::optional<Counts> incrementQ;
  std::optional<double> k; // the repeat count of a canned cycle
  // G04 (40), G28 (280), G29, G30, G31, G39 (390), G53 (530), the
  // look-ahead switches G05, G05.1, G05.4, G08 and a lathe's G70-G76.
  int nonModal = 0;
  bool selectsG541 = false;  // #4130 becomes its P
  double dwellSeconds = 0.0; // G04 X
  // A and D of a lathe's G76 in the Series 10/11 format.
  std::optional<double> tenFormatA;
  std::optional<double> tenFormatD;
  BlockCodes codes;
  FrameWords frames;
  bool flattened = false; // in the flattened program already
};

} // namespace mbc::rt
