// Lowering + verification, and the emit-ir command.
#include "driver/ir_pipeline.h"

#include "ir/lower.h"
#include "ir/printer.h"
#include "ir/verifier.h"

#include <cstdio>

namespace mbc::driver {

bool buildModule(const CompiledUnit& cu, ir::Module& out) {
  out = ir::lower(cu.unit, cu.sources);
  std::vector<std::string> problems = ir::verify(out);
  for (const std::string& p : problems) {
    std::fprintf(stderr, "mbc: internal error: invalid IR: %s\n", p.c_str());
  }
  return problems.empty();
}

int emitIrCommand(const std::vector<std::string>& files) {
  CompiledUnit cu;
  if (!loadUnit(files, false, cu)) {
    return 1;
  }
  ir::Module module;
  if (!buildModule(cu, module)) {
    return 4;
  }
  std::string text = ir::print(module);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

} // namespace mbc::driver
