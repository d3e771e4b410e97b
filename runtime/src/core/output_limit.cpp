// The output limit (--max-output): the bytes a run writes through its sinks
// are counted so that a runaway loop stops with MBC0003 instead of filling
// the disk long before the block limit would stop it.
#include <fmt/format.h>

#include <algorithm>

#include "context.h"

using namespace mbc::rt;

namespace mbc::rt {

void countOutput(mbrt_ctx& ctx, std::uint64_t bytes) {
  OutputBudget& output = ctx.run.output;
  const bool within = !output.passed();
  output.written += bytes;
  // A host that counted upper bounds says what they over-counted, and the
  // limit is checked on the exact bytes.
  const Sink<mbrt_settle_fn>& settle = ctx.host.outputSettle;
  if (within && output.passed() && settle.fn != nullptr) {
    output.written -= std::min(output.written, settle.fn(settle.user));
  }
  if (!within || !output.passed()) {
    return;
  }
  output.file = ctx.run.block.file;
  output.line = ctx.run.block.line;
  ctx.run.setBlockLimit(ctx.run.block.blocks);
}

void sendText(mbrt_ctx& ctx, const Sink<mbrt_text_fn>& sink,
              std::string_view text) {
  if (sink.fn != nullptr) {
    callSink(ctx, [&] { sink.fn(sink.user, text.data(), text.size()); });
    countOutput(ctx, text.size());
  }
}

mbrt_status raiseOutputLimit(mbrt_ctx& ctx) {
  ctx.run.block.file = ctx.run.output.file;
  ctx.run.block.line = ctx.run.output.line;
  return raise(ctx, AlarmId::OutputLimit,
               fmt::format("more than {} bytes written (--max-output)",
                           ctx.run.output.limit));
}

} // namespace mbc::rt

void mbrt_set_max_output(mbrt_ctx* ctx, uint64_t max_bytes) {
  ctx->run.output.limit = max_bytes != 0 ? max_bytes : kDefaultMaxOutput;
}

void mbrt_set_output_settle(mbrt_ctx* ctx, mbrt_settle_fn fn, void* user) {
  ctx->host.outputSettle = {fn, user};
}

void mbrt_count_output(mbrt_ctx* ctx, uint64_t bytes) {
  countOutput(*ctx, bytes);
}
