// POPEN, PCLOS, DPRNT and BPRNT (spec §7): lines built with print_format.h
// and sent to the print sink. mbc writes no DC2/DC4 device codes, so POPEN
// and PCLOS produce no bytes.
#include <fmt/format.h>

#include "context.h"
#include "print_format.h"

using namespace mbc;
using namespace mbc::rt;

namespace {

void sendLine(mbrt_ctx& ctx) {
  ctx.run.scratch += '\n';
  sendText(ctx, ctx.host.printSink, ctx.run.scratch);
}

} // namespace

mbrt_status mbrt_dprnt(mbrt_ctx* ctx, const mbrt_print_item* items,
                       size_t count) {
  mbrt_trace(ctx, "DPRNT");
  if (ctx->host.printSink.fn == nullptr) {
    return 0; // nothing in DPRNT can fail, so skip the formatting
  }
  const bool prt = ctx->profile.prt;
  std::string& line = ctx->run.scratch;
  line.clear();
  for (size_t i = 0; i < count; ++i) {
    const mbrt_print_item& item = items[i];
    line += item.text != nullptr ? formatPrintText(item.text)
                                 : formatDprntValue(item.value, item.int_digits,
                                                    item.frac_digits, prt);
  }
  sendLine(*ctx);
  return 0;
}

mbrt_status mbrt_bprnt(mbrt_ctx* ctx, const mbrt_print_item* items,
                       size_t count) {
  mbrt_trace(ctx, "BPRNT");
  std::string& line = ctx->run.scratch;
  line.clear();
  for (size_t i = 0; i < count; ++i) {
    const mbrt_print_item& item = items[i];
    if (item.text != nullptr) {
      line += formatPrintText(item.text);
    } else if (!appendBprntValue(line, item.value, item.frac_digits)) {
      return raise(*ctx, AlarmId::ArgumentOutOfRange,
                   fmt::format("BPRNT value {} does not fit in 32 bits",
                               numeric(item.value)));
    }
  }
  if (ctx->host.printSink.fn != nullptr) {
    sendLine(*ctx);
  }
  return 0;
}

mbrt_status mbrt_popen(mbrt_ctx* ctx) {
  mbrt_trace(ctx, "POPEN");
  return 0;
}

mbrt_status mbrt_pclos(mbrt_ctx* ctx) {
  mbrt_trace(ctx, "PCLOS");
  return 0;
}
