// libFuzzer target: any bytes as a Macro B file through the lexer, the
// parser, the semantic checks and the rendering of their diagnostics. It
// must never crash, hang or overflow the stack, whatever the input.
#include "frontend/diagnostics.h"
#include "frontend/parser.h"
#include "frontend/sema.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  mbc::SourceManager sources;
  mbc::DiagnosticEngine diags(sources);
  mbc::Unit unit;
  const std::uint32_t file = sources.add(
      "fuzz.nc", std::string(reinterpret_cast<const char*>(data), size));
  mbc::parseFile(sources, file, diags, mbc::ParseOptions{}, unit);
  mbc::checkUnit(unit, diags);
  (void)mbc::renderDiagnostics(diags);
  return 0;
}
