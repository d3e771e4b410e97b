// libFuzzer target: any bytes as a Macro B file through the lexer, the
// parser, the semantic checks and the rendering of their diagnostics. It
// must never crash, hang or overflow the stack, whatever the input.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  const mbc::fuzz::CheckedInput input(data, size);
  (void)mbc::renderDiagnostics(input.diags);
  return 0;
}
