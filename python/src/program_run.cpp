#include "program_run.h"

#include <mbc/engine.h>

#include "runner/output_files.h"
#include "runner/run_session.h"

namespace mbc::python {

namespace {

void appendText(void* user, const char* data, std::size_t size) {
  static_cast<std::string*>(user)->append(data, size);
}

AlarmParts alarmParts(const mbrt_ctx* ctx) {
  AlarmParts a;
  a.number = mbrt_alarm_number(ctx);
  a.code = runner::contextText(mbrt_alarm_code, ctx);
  a.message = runner::contextText(mbrt_alarm_message, ctx);
  a.report = runner::contextText(mbrt_alarm_report, ctx);
  a.file = mbrt_alarm_file(ctx);
  a.line = mbrt_alarm_line(ctx);
  const char* program = nullptr;
  const char* file = nullptr;
  int line = 0;
  for (std::size_t level = 0;
       mbrt_alarm_call(ctx, level, &program, &file, &line) != 0; ++level) {
    a.calls.emplace_back(program, file, line);
  }
  return a;
}

/// The sinks of a run its host watches: the output first, then the host.
struct Watched {
  RunOutput& out;
  const RunWatchers& watch;
};

void watchedMotion(void* user, const mbrt_motion* motion) {
  auto& w = *static_cast<Watched*>(user);
  MotionTable::append(&w.out.motions, motion);
  if (w.watch.motion != nullptr) {
    w.watch.motion(w.watch.user);
  }
}

void watchedPrint(void* user, const char* data, std::size_t size) {
  auto& w = *static_cast<Watched*>(user);
  w.out.dprnt.append(data, size);
  if (w.watch.print != nullptr) {
    w.watch.print(w.watch.user, data, size);
  }
}

} // namespace

runner::CtxPtr newContext(const std::string* profile, std::string& error) {
  char err[512] = "";
  runner::CtxPtr ctx(mbrt_create(
      profile != nullptr ? profile->c_str() : nullptr, err, sizeof err));
  if (!ctx) {
    error = err;
  }
  return ctx;
}

std::string axisNames(const mbrt_ctx* ctx) {
  mbrt_stats stats{};
  mbrt_get_stats(ctx, &stats);
  return std::string(stats.axis_names, stats.axis_count);
}

void runProgram(const CompiledProgram& program, mbrt_ctx* ctx,
                const RunRequest& request, RunOutput& out) {
  out.main = program.mainName();
  mbrt_buffer_motions(ctx, 0);
  Watched watched{out, request.watch};
  const bool watching = request.watch.user != nullptr;
  if (watching) {
    mbrt_set_motion_sink(ctx, &watchedMotion, &watched);
    mbrt_set_print_sink(ctx, &watchedPrint, &watched);
    mbrt_set_alarm_sink(ctx, request.watch.alarm, request.watch.user);
  } else {
    mbrt_set_motion_sink(ctx, &MotionTable::append, &out.motions);
    mbrt_set_print_sink(ctx, &appendText, &out.dprnt);
  }
  mbrt_set_message_sink(ctx, &appendText, &out.messages);
  mbrt_set_max_blocks(ctx, request.maxBlocks);
  mbrt_start(ctx, out.main.c_str());
  runner::RunOptions options;
  options.args = request.args;
  options.presets = request.presets;
  out.status = runner::presetAndPass(options, ctx);
  if (out.status == MBRT_OK) {
    out.status = program.prepared().run(ctx);
  }
  mbrt_set_motion_sink(ctx, nullptr, nullptr);
  mbrt_set_print_sink(ctx, nullptr, nullptr);
  mbrt_set_message_sink(ctx, nullptr, nullptr);
  mbrt_set_alarm_sink(ctx, nullptr, nullptr);
  if (out.status != MBRT_OK) {
    out.alarm = alarmParts(ctx);
  }
  out.programs = out.motions.programs();
  out.files = out.motions.files();
  mbrt_get_stats(ctx, &out.stats);
  out.unit = out.stats.unit;
  out.axes.assign(out.stats.axis_names, out.stats.axis_count);
  out.stats.unit = nullptr;
  out.stats.axis_names = nullptr;
  out.variables = runner::commonVariables(ctx);
}

} // namespace mbc::python
