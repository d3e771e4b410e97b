// The mbc command: `mbc run` executes a Macro B program, `mbc check` only
// reports diagnostics, `mbc emit-ir` prints the (optimised) IR, `mbc compile`
// writes an object and `mbc build` an executable.
#include "driver/compile_command.h"
#include "driver/compile_unit.h"
#include "driver/ir_pipeline.h"
#include "driver/options.h"
#include "driver/run_command.h"

#include <cstdio>

int main(int argc, char** argv) {
  using namespace mbc::driver;
  std::string error;
  std::optional<Options> options = parseOptions(argc, argv, error);
  if (!options) {
    std::fprintf(stderr, "mbc: error: %s\n%s", error.c_str(),
                 usageText().c_str());
    return 2;
  }
  if (options->command == "emit-ir") {
    return emitIrCommand(*options);
  }
  if (options->command == "compile") {
    return compileCommand(*options);
  }
  if (options->command == "build") {
    return buildCommand(*options);
  }
  if (options->command == "check") {
    CompiledUnit cu;
    return loadUnit(options->files, true, cu) ? 0 : 1;
  }
  return runCommand(*options);
}
