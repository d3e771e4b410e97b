// One run of a main program, whatever engine runs it: the context from the
// machine profile, the sinks and output files, presets and arguments, then
// the alarm report, the variables file and the summary line. `mbc run` and
// the executables of `mbc build` share it, so they behave alike.
#pragma once

#include <mbc/runtime.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runner/run_options.h"

namespace mbc::runner {

/// Runs the main program in a context that is set up and started.
using MainRun = std::function<mbrt_status(mbrt_ctx*)>;

/// Wall-clock milliseconds of the phases before the run, by name, for
/// --time.
using PhaseTimes = std::vector<std::pair<const char*, double>>;

struct CtxDeleter {
  void operator()(mbrt_ctx* c) const { mbrt_destroy(c); }
};

using CtxPtr = std::unique_ptr<mbrt_ctx, CtxDeleter>;

/// A context for the options' machine profile; null after telling stderr
/// why the profile is bad.
CtxPtr createContext(const RunOptions& o);

/// Where a run reports (the operator messages, the trace, the alarm report
/// and the summary lines) and what a batch keeps of it. With `capture`, the
/// toolpath, DPRNT and variables are kept here instead of written to the
/// options' files.
struct SessionLog {
  std::FILE* text = stderr;
  bool capture = false;
  std::string toolpath, dprnt, vars;
  std::string alarm; // the alarm report's first line, "" after a normal end
  mbrt_stats stats{};
};

/// One run in `ctx`, which must be as mbrt_create or mbrt_reset left it and
/// outlive an InterruptScope around the run. Returns the exit status of
/// `mbc run`: 0, 2 (bad state or output file), 3 (an alarm stopped the run)
/// or 128 + the signal that stopped it.
int runSession(const RunOptions& o, mbrt_ctx* ctx, const std::string& mainName,
               const MainRun& engine, SessionLog& log,
               const PhaseTimes& phases = {});

/// The presets (mbrt_preset_var) then the main program's arguments (as G65
/// passes them, real values) of a started run: 0 or the alarm.
mbrt_status presetAndPass(const RunOptions& o, mbrt_ctx* ctx);

/// `mbc run`'s session: a context, the signal handlers, one run reporting to
/// stderr. 2 for a bad machine profile.
int runOnce(const RunOptions& o, const std::string& mainName,
            const MainRun& engine, const PhaseTimes& phases = {});

/// A text the C API writes snprintf-style, whole (mbrt_alarm_code,
/// mbrt_alarm_message, mbrt_alarm_report).
std::string contextText(std::size_t (*get)(const mbrt_ctx*, char*, std::size_t),
                        const mbrt_ctx* ctx);

/// A cycle time as the summary prints it: "1:02:03.4" or "2:03.4".
std::string clockText(double seconds);

/// Milliseconds since `start`.
double millisecondsSince(std::chrono::steady_clock::time_point start);

} // namespace mbc::runner
