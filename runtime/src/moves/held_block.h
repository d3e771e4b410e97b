// A chamfer or corner R holds its block's move until the next block tells
// where the corner goes; the moves it then makes belong to the held block
// and run in that block's state (context.h BlockState), not in the state
// the next block has set up: a G41/G42 or D, a tool length or lathe tool
// offset, an F of the next block act from the next block's own move.
#pragma once

#include <optional>

#include "context.h"
#include "corner_state.h"
#include "frames.h"
#include "move_state.h"

namespace mbc::rt {

/// The state of the block running now, for a move it holds.
BlockState captureBlock(const mbrt_ctx& ctx);

/// While it lives, the context is in the held block's state, its file and
/// line included; the running block's state comes back after.
class InHeldBlock {
public:
  InHeldBlock(mbrt_ctx& ctx, const CornerInsertion& held);
  ~InHeldBlock();
  InHeldBlock(const InHeldBlock&) = delete;
  InHeldBlock& operator=(const InHeldBlock&) = delete;

private:
  mbrt_ctx& ctx_;
  BlockState own_;
  const char* file_;
  int line_;
  std::optional<PlacedAs> placed_; // after the modal state: its work offset
};

/// Runs `moves` in the held block's state.
template <class Moves>
mbrt_status asHeldBlock(mbrt_ctx& ctx, const CornerInsertion& held,
                        Moves moves) {
  const InHeldBlock scope(ctx, held);
  return moves();
}

/// MBC0001 while a chamfer or corner R waits for its next move and the
/// block would change `what` under it, or 0: the corner's two moves would
/// lie in two coordinate systems.
mbrt_status refuseUnderHeldCorner(mbrt_ctx& ctx, std::string_view what);

/// MBC0001 for what mbc does not model under compensation, or 0 when
/// compensation is off.
mbrt_status refuseUnderCompensation(mbrt_ctx& ctx, std::string_view what);

/// The same under cutter compensation too (refuseUnderCompensation): a
/// change of coordinate system that no held move may span.
mbrt_status refuseUnderHeldMoves(mbrt_ctx& ctx, std::string_view what);

} // namespace mbc::rt
