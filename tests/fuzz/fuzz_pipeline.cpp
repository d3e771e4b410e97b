// libFuzzer target: a Macro B file that the front end accepts, lowered to
// IR, verified, optimised with the verifier after every pass, and printed;
// the printed IR must parse back to the same text. A verifier failure or a
// failed round trip is a compiler bug, so it aborts (libFuzzer reports it
// as a crash with the input).
#include "ir/ir_parser.h"
#include "ir/lower.h"
#include "ir/pass_manager.h"
#include "ir/printer.h"
#include "ir/verifier.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz_input.h"

namespace {

void failIf(bool failed, const char* what, const std::string& detail) {
  if (failed) {
    std::fprintf(stderr, "fuzz_pipeline: %s\n%s\n", what, detail.c_str());
    std::abort();
  }
}

std::string joined(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& p : problems) {
    text += p + "\n";
  }
  return text;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  const mbc::fuzz::CheckedInput input(data, size);
  if (input.diags.errorCount() > 0) {
    return -1; // not a program: keep it out of the corpus
  }
  for (const bool trace : {false, true}) {
    mbc::ir::Module module =
        mbc::ir::lower(input.unit, input.sources, mbc::ir::LowerOptions{trace});
    const auto lowered = mbc::ir::verify(module);
    failIf(!lowered.empty(), "invalid IR after lowering", joined(lowered));
    std::string error;
    failIf(!mbc::ir::runPasses(module, mbc::ir::PassOptions{{}, true}, error),
           "a pass failed", error);
    const std::string text = mbc::ir::print(module);
    mbc::ir::Module reparsed;
    failIf(!mbc::ir::parseModule(text, reparsed, error),
           "the printed IR does not parse", error + "\n" + text);
    failIf(mbc::ir::print(reparsed) != text,
           "the printed IR parses to a different module", text);
  }
  return 0;
}
