// `mbc run`: execute the main program and write its toolpath, DPRNT output
// and variables.
#pragma once

#include "driver/options.h"

namespace mbc::driver {

/// Returns the process exit status: 0 normal end, 1 source errors, 2 usage
/// (bad machine profile, missing main program), 3 alarm.
int runCommand(const Options& options);

} // namespace mbc::driver
