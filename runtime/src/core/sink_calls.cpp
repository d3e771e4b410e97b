// Calls an embedder makes from inside one of the context's sinks. A motion
// or text callback runs in the middle of a block: restarting, resetting or
// freeing the context there would pull the run's state from under the
// block that called it, so such calls do nothing and stop the run instead.
#include "context.h"

namespace mbc::rt {

bool refuseInSink(mbrt_ctx& ctx, const char* function) {
  if (ctx.run.sinkDepth == 0) {
    return false;
  }
  if (ctx.run.refusedInSink == nullptr) {
    ctx.run.refusedInSink = function;
  }
  ctx.run.setBlockLimit(0);
  return true;
}

} // namespace mbc::rt
