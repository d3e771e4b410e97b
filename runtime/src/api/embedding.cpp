// What embedders get beyond the plain sinks: a run of a compiled program
// as the main program, an alarm callback and a toolpath buffer in the
// context, for callers that would rather read the motions of a run than
// receive them one by one.
#include "context.h"

namespace {

void bufferMotion(void* user, const mbrt_motion* motion) {
  auto* ctx = static_cast<mbrt_ctx*>(user);
  mbrt_motion copy = *motion;
  // The caller's program name lives in its call record, which is gone
  // after the call returns.
  copy.program = ctx->host.bufferedNames.insert(motion->program).first->c_str();
  ctx->host.motionBuffer.push_back(copy);
  mbc::rt::countOutput(*ctx, sizeof copy);
}

} // namespace

void mbrt_set_alarm_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user) {
  ctx->host.alarmSink = {fn, user};
}

void mbrt_buffer_motions(mbrt_ctx* ctx, int on) {
  ctx->host.motionSink = on ? mbc::rt::Sink<mbrt_motion_fn>{bufferMotion, ctx}
                            : mbc::rt::Sink<mbrt_motion_fn>{};
  ctx->host.motionBuffer.clear();
}

const mbrt_motion* mbrt_buffered_motions(const mbrt_ctx* ctx, size_t* count) {
  *count = ctx->host.motionBuffer.size();
  return ctx->host.motionBuffer.data();
}

/// A run of a compiled program as the main program: mbrt_start, the
/// arguments, the body.
mbrt_status mbrt_run_main(mbrt_ctx* ctx, const mbrt_program* program,
                          const mbrt_word* args, size_t count) {
  if (mbc::rt::refuseInSink(*ctx, "mbrt_run_main")) {
    return static_cast<mbrt_status>(mbc::AlarmId::CalledFromSink);
  }
  mbrt_start(ctx, program->name);
  if (count > 0) {
    if (const mbrt_status st = mbrt_set_main_args(ctx, args, count)) {
      return st;
    }
  }
  const mbrt_status st = mbrt_run_body(ctx, program);
  // The run is over: what the host calls next is no block's doing.
  ctx->run.block.file = nullptr;
  ctx->run.block.line = 0;
  return st;
}
