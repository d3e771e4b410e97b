// `mbc run`: the input compiled for the chosen engine, then one run session.
#include "driver/run_command.h"

#include "driver/prepared_program.h"
#include "driver/run_session.h"

namespace mbc::driver {

int runCommand(const Options& o) {
  PhaseTimes phases;
  PreparedProgram program;
  if (int status = program.prepare(o, phases)) {
    return status == PreparedProgram::kNothingToRun ? 0 : status;
  }
  return runOnce(
      o.run, program.mainName(),
      [&program](mbrt_ctx* ctx) { return program.run(ctx); }, phases);
}

} // namespace mbc::driver
