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

mbrt_level* mbrt_current_level(mbrt_ctx* ctx) {
  return &ctx->locals();
}

mbrt_num* mbrt_common_base(mbrt_ctx* ctx) {
  return ctx->data.commons.data();
}

mbrt_block_state* mbrt_block_state_of(mbrt_ctx* ctx) {
  return &ctx->run.block;
}

mbrt_status mbrt_nc_steps(mbrt_ctx* ctx, const mbrt_nc_run* run, size_t first,
                          mbrt_flow* flow, size_t* next) {
  std::vector<mbrt_word>& words = ctx->run.stepWords;
  for (size_t i = first; i < run->count; ++i) {
    *next = i + 1;
    const int32_t* step = run->steps + 3 * i;
    words.resize(static_cast<size_t>(step[1]));
    for (size_t k = 0; k < words.size(); ++k) {
      const size_t word = static_cast<size_t>(step[2]) + k;
      words[k] = {static_cast<char>(run->codes[2 * word]),
                  run->codes[2 * word + 1], run->values[word]};
    }
    if (mbrt_status st = mbrt_begin_block(ctx, run->file, step[0])) {
      return st;
    }
    if (mbrt_status st = mbrt_nc_block(ctx, words.data(), words.size(), flow)) {
      return st;
    }
    if (flow->kind != MBRT_FLOW_NEXT || flow->has_seq != 0) {
      return 0;
    }
  }
  return 0;
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
  // The same rounding as the address's own (a decimal tie such as 1.0005
  // rounds up although 1.0005 / 0.001 is 1000.4999...), in whole
  // increments per unit so that the result is the nearest double. A value
  // that rounds to zero is +0 like every macro value: -0.0001 gave -0, which
  // the interpreter's subtraction made +0 and the JIT's kept.
  const double perUnit = addressCountsPerUnit(*ctx, static_cast<char>(letter));
  *out = positiveZero(roundToCounts(numeric(x), perUnit) / perUnit);
  return 0;
}
