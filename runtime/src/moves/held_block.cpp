// The state a held chamfer or corner R runs in (held_block.h).
#include "held_block.h"

#include <fmt/format.h>

#include "corner_state.h"
#include "cutter_comp_state.h"

namespace mbc::rt {

BlockState captureBlock(const mbrt_ctx& ctx) {
  return {ctx.machine.modal,
          placementOf(ctx),
          ctx.machine.lastWords[lastWordSlot(LastWord::D)],
          ctx.machine.lastWords[lastWordSlot(LastWord::S)],
          ctx.compensation->codeInBlock,
          ctx.machine.feedInBlock};
}

InHeldBlock::InHeldBlock(mbrt_ctx& ctx, const CornerInsertion& held)
    : ctx_(ctx), own_(captureBlock(ctx)), file_(ctx.run.block.file),
      line_(ctx.run.block.line) {
  const BlockState& block = held.block;
  ctx.machine.modal = block.modal;
  ctx.machine.lastWords[lastWordSlot(LastWord::D)] = block.dWord;
  ctx.machine.lastWords[lastWordSlot(LastWord::S)] = block.sWord;
  ctx.compensation->codeInBlock = block.codeInBlock;
  ctx.machine.feedInBlock = block.feedInBlock;
  ctx.run.block.file = held.file;
  ctx.run.block.line = held.line;
  placed_.emplace(ctx, block.placement);
}

InHeldBlock::~InHeldBlock() {
  placed_.reset();
  ctx_.machine.modal = own_.modal;
  ctx_.machine.lastWords[lastWordSlot(LastWord::D)] = own_.dWord;
  ctx_.machine.lastWords[lastWordSlot(LastWord::S)] = own_.sWord;
  ctx_.compensation->codeInBlock = own_.codeInBlock;
  ctx_.machine.feedInBlock = own_.feedInBlock;
  ctx_.run.block.file = file_;
  ctx_.run.block.line = line_;
}

mbrt_status refuseUnderCompensation(mbrt_ctx& ctx, std::string_view what) {
  if (!compensating(ctx)) {
    return 0;
  }
  return raise(ctx, AlarmId::Unsupported,
               fmt::format("{} in cutter compensation mode (G41/G42); "
                           "give it after G40",
                           what));
}

mbrt_status refuseUnderHeldCorner(mbrt_ctx& ctx, std::string_view what) {
  if (!ctx.corner->pending) {
    return 0;
  }
  return raise(ctx, AlarmId::Unsupported,
               fmt::format("{} between a chamfer, corner R or ,A line (line "
                           "{}) and the move that makes its corner",
                           what, ctx.corner->line));
}

mbrt_status refuseUnderHeldMoves(mbrt_ctx& ctx, std::string_view what) {
  if (const mbrt_status status = refuseUnderCompensation(ctx, what)) {
    return status;
  }
  return refuseUnderHeldCorner(ctx, what);
}

} // namespace mbc::rt
