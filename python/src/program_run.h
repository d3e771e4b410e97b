// One run of a compiled program on a context, as `mbc run` makes it (the
// same start, presets, arguments and engine), with everything it outputs
// kept for Python: the motions, DPRNT and operator messages, the alarm in
// parts, the statistics and the common variables at the end.
#pragma once

#include <mbc/runtime.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiled_program.h"
#include "motion_table.h"
#include "runner/run_session.h"

namespace mbc::python {

/// What a host watches as a run goes (Python's Machine callbacks): each is
/// called with `user` after the run has kept what it reports (the motion
/// is the table's last row by then); null for none.
struct RunWatchers {
  void (*motion)(void* user) = nullptr;
  mbrt_text_fn print = nullptr;
  mbrt_text_fn alarm = nullptr;
  void* user = nullptr;
};

struct RunRequest {
  std::vector<std::pair<char, double>> args;      // G65-style, real values
  std::vector<std::pair<double, double>> presets; // #N = value, before
  std::uint64_t maxBlocks = 0;                    // 0: the default limit
  RunWatchers watch;
};

struct AlarmParts {
  int number = 0;
  std::string code, message, file, report;
  int line = 0;
  std::vector<std::tuple<std::string, std::string, int>> calls; // innermost
};

struct RunOutput {
  RunOutput(std::string axisLetters, NameTable& programNames,
            NameTable& fileNames)
      : motions(std::move(axisLetters), programNames, fileNames) {}

  std::string main;
  mbrt_status status = MBRT_OK;
  std::optional<AlarmParts> alarm;
  MotionTable motions;
  // The names its rows' prog and file columns index, as they stood at the
  // end of the run (the tables go on with the machine's next runs).
  std::vector<std::string> programs, files;
  std::string dprnt, messages;
  mbrt_stats stats{};     // its names point into the context: not kept
  std::string unit, axes; // so these are copies
  std::vector<std::pair<int, double>> variables; // the commons set
};

/// A context for a machine profile's JSON (nullptr: the built-in mill);
/// null with the reason in `error` for a bad profile.
runner::CtxPtr newContext(const std::string* profile, std::string& error);

/// The axis letters of the context's machine ("XYZ").
std::string axisNames(const mbrt_ctx* ctx);

/// Runs the program's main program on `ctx` from its current state; needs
/// no Python (the caller may release the GIL).
void runProgram(const CompiledProgram& program, mbrt_ctx* ctx,
                const RunRequest& request, RunOutput& out);

} // namespace mbc::python
