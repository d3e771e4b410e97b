// How the options say the input is read.
#include "driver/options.h"

namespace mbc::driver {

LoadOptions loadOptions(const Options& o) {
  const bool runs = o.command == "run" || o.command == "batch";
  LoadOptions load;
  load.defaultMachine = o.run.machinePath.empty() && o.command != "compile" &&
                        o.command != "build";
  load.errors = o.strict.value_or(!runs) ? ErrorMode::Refuse : ErrorMode::Alarm;
  load.includeDirs = o.includeDirs;
  load.diagnostics = o.diagnostics;
  return load;
}

} // namespace mbc::driver
