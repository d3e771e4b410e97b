// The calls an NC block makes besides M98 (spec §5.6, §5.7): G66/G66.1 modal
// calls, custom G and M code macros, and subprograms called by M, T, S and
// B codes. The runtime decides them; the engine makes them (MBRT_FLOW_CALL).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "context.h"

namespace mbc::rt {

/// What a block did that may call a program after it executed.
struct BlockCodes {
  bool moved = false; // the block had axis words
  int mCount = 0;
  std::array<int, 3> m{};
  std::optional<double> t;
  std::optional<double> s;
  std::optional<double> b; // when B is no axis
};

/// "M3." or "P2.5": a word written with a decimal point, as written (the
/// PS0007 of a number or count that takes none).
std::string pointedWordText(char letter, double value);

/// Before a block executes: G66, G66.1 and G67 themselves, and the calls
/// that take the block's place (G66.1 in force, custom G and M code macros).
/// `taken` tells that nothing of the block is left to execute.
mbrt_status callInsteadOfBlock(mbrt_ctx& ctx, const mbrt_word* words,
                               size_t count, mbrt_flow* flow, bool* taken);

/// After a block executed: M, T, S, B code subprograms and G66 after a
/// move. A block asks for one transfer at most: a second one alarms.
/// Only with code calls in the profile or a modal call in force.
mbrt_status callAfterBlock(mbrt_ctx& ctx, const BlockCodes& codes,
                           mbrt_flow* flow);

} // namespace mbc::rt
