// How the options say the input is read.
#include "driver/options.h"

namespace mbc::driver {

toolchain::LoadOptions loadOptions(const Options& o) {
  const bool runs = o.command == "run" || o.command == "batch";
  toolchain::LoadOptions load;
  load.defaultMachine = o.run.machinePath.empty() && o.command != "compile" &&
                        o.command != "build";
  load.errors = o.strict.value_or(!runs) ? ErrorMode::Refuse : ErrorMode::Alarm;
  load.includeDirs = o.includeDirs;
  load.diagnostics = o.diagnostics;
  if (o.command == "check" && (o.prove || !o.argRanges.empty())) {
    load.alarmRanges =
        toolchain::AlarmRangeRequest{o.run.mainProgram, o.argRanges};
  }
  return load;
}

toolchain::Request toolchainRequest(const Options& o) {
  toolchain::Request request;
  request.files = o.files;
  request.load = loadOptions(o);
  request.engine = o.engine;
  request.mainProgram = o.run.mainProgram;
  request.trace = o.run.trace;
  request.passes = {!o.noOpt, o.verifyEach, o.disabledPasses};
  request.code = {o.optLevel, o.sizeLevel, o.debugInfo};
  request.useCache = !o.noCache;
  return request;
}

} // namespace mbc::driver
