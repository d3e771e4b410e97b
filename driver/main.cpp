// The mbc command: `mbc run` executes a Macro B program, `mbc check` only
// reports diagnostics, `mbc batch` runs it once per row of a table, `mbc
// emit-ir` prints the (optimised) IR, `mbc compile` writes an object and `mbc
// build` an executable.
#include "driver/batch_command.h"
#include "driver/check_command.h"
#include "driver/command_line.h"
#include "driver/compile_command.h"
#include "driver/emit_ir_command.h"
#include "driver/run_command.h"

#include <cstdio>
#include <exception>
#include <new>

#include "lsp/server.h"

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
    return checkCommand(*options);
  }
  if (options->command == "lsp") {
    return mbc::lsp::runServer(fileno(stdin), stdout);
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
