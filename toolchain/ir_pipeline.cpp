// Lowering, verification and the passes.
#include "toolchain/ir_pipeline.h"

#include "ir/lower.h"
#include "ir/pass_manager.h"
#include "ir/verifier.h"

#include <cstdio>

namespace mbc::toolchain {

namespace {

// Debug builds verify after every pass even without --verify-each.
#ifdef NDEBUG
constexpr bool kVerifyEachByDefault = false;
#else
constexpr bool kVerifyEachByDefault = true;
#endif

} // namespace

bool verifyModule(const ir::Module& m, const char* what) {
  const std::vector<std::string> problems = ir::verify(m);
  for (const std::string& p : problems) {
    std::fprintf(stderr, "mbc: %s: %s\n", what, p.c_str());
  }
  return problems.empty();
}

bool buildModule(const CompiledUnit& cu, bool trace, ir::Module& out) {
  out = ir::lower(cu.unit, cu.sources, ir::LowerOptions{trace});
  return verifyModule(out, "internal error: invalid IR");
}

bool optimizeModule(ir::Module& m, const IrPasses& passes) {
  if (!passes.run) {
    return true;
  }
  ir::PassOptions po{passes.disabled,
                     passes.verifyEach || kVerifyEachByDefault};
  std::string error;
  if (!ir::runPasses(m, po, error)) {
    std::fprintf(stderr, "mbc: internal error: %s\n", error.c_str());
    return false;
  }
  return verifyModule(m, "internal error: invalid IR after the passes");
}

} // namespace mbc::toolchain
