// One run of a main program, whatever engine runs it: the context from the
// machine profile, the sinks and output files, presets and arguments, then
// the alarm report, the variables file and the summary line. `mbc run` and
// the executables of `mbc build` share it, so they behave alike.
#pragma once

#include "driver/run_options.h"
#include <mbc/runtime.h>

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mbc::driver {

/// Runs the main program in a context that is set up and started.
using Engine = std::function<mbrt_status(mbrt_ctx*)>;

/// Wall-clock milliseconds of the phases before the run, by name, for
/// --time.
using PhaseTimes = std::vector<std::pair<const char*, double>>;

/// Returns the exit status of `mbc run`: 0, 2 (bad machine profile or
/// output file) or 3 (an alarm stopped the run).
int runSession(const RunOptions& o, const std::string& mainName,
               const Engine& engine, const PhaseTimes& phases = {});

/// Milliseconds since `start`.
double millisecondsSince(std::chrono::steady_clock::time_point start);

} // namespace mbc::driver
