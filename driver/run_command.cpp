// `mbc run`: the input compiled for the chosen engine, then one run session.
#include "driver/run_command.h"

#include "runner/run_session.h"
#include "toolchain/prepared_program.h"

namespace mbc::driver {

int runCommand(const Options& o) {
  runner::PhaseTimes phases;
  toolchain::PreparedProgram program;
  if (int status = program.prepare(toolchainRequest(o), phases)) {
    return status == toolchain::PreparedProgram::kNothingToRun ? 0 : status;
  }
  return runner::runOnce(
      o.run, program.mainName(),
      [&program](mbrt_ctx* ctx) { return program.run(ctx); }, phases);
}

} // namespace mbc::driver
