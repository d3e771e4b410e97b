// The mbc command: `mbc run` executes a Macro B program, `mbc check` only
// reports diagnostics, `mbc batch` runs it once per row of a table, `mbc
// emit-ir` prints the (optimised) IR, `mbc compile` writes an object and `mbc
// build` an executable.
#include "driver/batch_command.h"
#include "driver/command_line.h"
#include "driver/compile_command.h"
#include "driver/emit_ir_command.h"
#include "driver/run_command.h"
#include <mbc/engine.h>

#include <cstdio>
#include <exception>
#include <new>
#include <string_view>

#include "runner/run_session.h"
#include "toolchain/compile_unit.h"

namespace {

int dispatch(int argc, char** argv) {
  using namespace mbc::driver;
  CommandLine line = parseCommandLine(argc, argv);
  std::optional<Options>& options = line.options;
  if (!options) {
    return line.status;
  }
  if (options->command == "emit-ir") {
    return emitIrCommand(*options);
  }
  if (options->command == "compile") {
    return compileCommand(*options);
  }
  if (options->command == "batch") {
    return batchCommand(*options);
  }
  if (options->command == "build") {
    return buildCommand(*options);
  }
  if (options->command == "check") {
    mbc::toolchain::CompiledUnit cu;
    // A profile given is checked too, and the checks defer to it.
    mbc::toolchain::LoadOptions load = loadOptions(*options);
    if (!options->run.machinePath.empty()) {
      const mbc::runner::CtxPtr machine =
          mbc::runner::createContext(options->run);
      if (!machine) {
        return 2;
      }
      load.latheSystem = static_cast<char>(mbrt_lathe_system(machine.get()));
      mbrt_stats stats{};
      mbrt_get_stats(machine.get(), &stats);
      load.inch = std::string_view(stats.unit) == "inch";
      load.decimalPointInput =
          (static_cast<long>(mbrt_parameter(machine.get(), 3401)) & 1) != 0;
    }
    load.checkWarnings = true;
    if (!mbc::toolchain::loadUnit(options->files, load, cu)) {
      return 1;
    }
    if (options->prove) {
      // The verdict after the findings, as the last line.
      if (cu.blocksThatMayAlarm > 0) {
        std::fprintf(stderr, "mbc: not proved: %d block%s may raise an alarm\n",
                     cu.blocksThatMayAlarm,
                     cu.blocksThatMayAlarm == 1 ? "" : "s");
        return 1;
      }
      std::fputs("mbc: proved: no block can raise an alarm the range "
                 "analysis decides\n",
                 stderr);
    }
    return 0;
  }
  return runCommand(*options);
}

} // namespace

// Whatever escapes is reported with the exit status of an internal error
// rather than an abort: out of memory (a huge program under a memory limit)
// or a bug.
int main(int argc, char** argv) {
  try {
    return dispatch(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fputs("mbc: error: out of memory\n", stderr);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mbc: internal error: %s\n", e.what());
  }
  return 4;
}
