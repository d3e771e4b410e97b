// mbc's command line: its commands, their options and their help.
#pragma once

#include "driver/options.h"

#include <optional>

namespace mbc::driver {

struct CommandLine {
  /// What to do; empty when the line was only a question (help, version)
  /// or wrong, with `status` the exit status.
  std::optional<Options> options;
  int status = 0;
};

/// Reads argv. Help (`mbc --help`, `mbc help CMD`, `mbc CMD --help`) and
/// `--version` are printed on standard output (status 0); a usage error
/// is reported on standard error (status 2).
CommandLine parseCommandLine(int argc, char** argv);

} // namespace mbc::driver
