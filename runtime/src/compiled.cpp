// The operations generated code leaves to the runtime (mbc/compiled.h):
// storage addresses, and the arithmetic of mbc/arith.h with its alarms.
#include <mbc/arith.h>
#include <mbc/compiled.h>

#include "context.h"

using namespace mbc;
using namespace mbc::rt;

// Generated code indexes mbrt_level by the C layout.
static_assert(sizeof(LocalLevel) == sizeof(mbrt_level));

namespace {

MathParams mathParams(const mbrt_ctx& ctx) {
  MathParams params;
  params.nat = ctx.profile.nat;
  return params;
}

mbrt_status check(mbrt_ctx& ctx, AlarmId id) {
  return id == AlarmId::None ? 0 : raise(ctx, id);
}

} // namespace

mbrt_block_state* mbrt_block_state_of(mbrt_ctx* ctx) {
  return &ctx->block;
}

mbrt_status mbrt_binary(mbrt_ctx* ctx, int op, double a, double b,
                        double* out) {
  return check(*ctx, evalBinary(static_cast<BinOp>(op), a, b, out));
}

mbrt_status mbrt_builtin(mbrt_ctx* ctx, int builtin, double a, double b,
                         double* out) {
  const Num args[2] = {a, b};
  return check(*ctx, evalBuiltin(static_cast<Builtin>(builtin), args,
                                 mathParams(*ctx), out));
}

mbrt_status mbrt_round_address(mbrt_ctx* ctx, int letter, double x,
                               double* out) {
  const double inc = mbrt_address_increment(ctx, static_cast<char>(letter));
  *out = roundHalfAway(numeric(x) / inc) * inc;
  return 0;
}
