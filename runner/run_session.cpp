// A run and its summary lines (see run_session.h).
#include "runner/run_session.h"

#include <mbc/alarm.h>
#include <mbc/engine.h>

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "runner/html_page.h"
#include "runner/html_writer.h"
#include "runner/interrupt_scope.h"
#include "runner/output_files.h"
#include "runner/state_file.h"
#include "runner/svg_writer.h"
#include "runner/toolpath_thread.h"

namespace mbc::runner {

namespace {

void writeLog(void* log, const char* data, std::size_t size) {
  std::fwrite(data, 1, size, static_cast<std::FILE*>(log));
}

/// A box limit to print with 3 decimals: an arc's extreme a rounding error
/// below zero (-1e-15) reads 0.000, not -0.000.
double boxLimit(double value) {
  return std::fabs(value) < 0.0005 ? 0.0 : value;
}

/// Path lengths, the estimated cycle time and the bounding box.
std::string toolpathSummary(const mbrt_stats& st) {
  std::string box;
  for (int axis = 0; axis < st.axis_count; ++axis) {
    box += fmt::format(" {} {:.3f}..{:.3f}", st.axis_names[axis],
                       boxLimit(st.box_min[axis]), boxLimit(st.box_max[axis]));
  }
  return fmt::format(
      "mbc: toolpath ({}): feed {:.3f}, rapid {:.3f}, time {};{}\n", st.unit,
      st.feed_length, st.rapid_length, clockText(st.cycle_time), box);
}

void printSummary(const mbrt_stats& st, const std::string& program,
                  bool alarmed, std::FILE* log) {
  std::fprintf(log, "mbc: %s: %llu blocks, %llu moves, %d alarm%s\n",
               program.c_str(), static_cast<unsigned long long>(st.blocks),
               static_cast<unsigned long long>(st.moves), alarmed ? 1 : 0,
               alarmed ? "" : "s");
  if (st.moves > 0) {
    std::fputs(toolpathSummary(st).c_str(), log);
  }
  if (st.optional_stops) {
    std::fprintf(log, "mbc: note: %llu M00/M01 stop(s) passed through\n",
                 static_cast<unsigned long long>(st.optional_stops));
  }
  if (st.main_m99) {
    std::fprintf(log, "mbc: note: M99 in the main program ended the run "
                      "(a control would start it again)\n");
  }
}

/// The pictures' title: program, machine, moves, cycle time, alarm.
std::string pictureTitle(const RunOptions& o, mbrt_ctx* ctx,
                         const std::string& program, mbrt_status status) {
  mbrt_stats st{};
  mbrt_get_stats(ctx, &st);
  const std::string machine =
      o.machinePath.empty()
          ? std::string("built-in 3-axis mill")
          : std::filesystem::path(o.machinePath).filename().string();
  return fmt::format("{} \u00b7 machine {} \u00b7 {} moves \u00b7 cycle {}{}",
                     program, machine, st.moves, clockText(st.cycle_time),
                     status != 0 ? " \u00b7 stopped by an alarm" : "");
}

/// The flattened program is one ISO tape: '%', the blocks, '%'.
bool openGcode(const RunOptions& o, mbrt_ctx* ctx, OutputFile& gcode) {
  if (o.gcodePath.empty()) {
    return true;
  }
  if (!gcode.open(o.gcodePath)) {
    std::fprintf(stderr, "mbc: error: cannot write '%s'\n",
                 o.gcodePath.c_str());
    return false;
  }
  OutputFile::writeText(&gcode, "%\n", 2);
  mbrt_set_gcode_sink(ctx, &OutputFile::writeText, &gcode);
  return true;
}

/// Where the motions go: the toolpath file, the drawing and the page, any
/// of them. All count against the output limit: the pictures grow in
/// memory.
struct MotionOutputs {
  mbrt_ctx* ctx = nullptr;
  OutputFile toolpath;
  std::optional<SvgWriter> svg;
  std::optional<HtmlWriter> html;
  std::optional<ToolpathThread> writer; // when worthwhile
  MotionTargets here;                   // made on the run's thread

  static void write(void* self, const mbrt_motion* motion) {
    auto* outputs = static_cast<MotionOutputs*>(self);
    std::size_t bytes = outputs->here.take(*motion);
    if (outputs->writer) {
      bytes += outputs->writer->push(*motion);
    }
    mbrt_count_output(outputs->ctx, bytes);
  }

  static std::uint64_t settle(void* self) {
    auto* outputs = static_cast<MotionOutputs*>(self);
    return outputs->writer ? outputs->writer->settle() : 0;
  }
};

/// The toolpath, the drawing and DPRNT: files (DPRNT defaults to standard
/// output) or, with `capture`, memory.
bool openOutputs(const RunOptions& o, mbrt_ctx* ctx, MotionOutputs& motions,
                 OutputFile& dprnt, bool capture) {
  motions.ctx = ctx;
  if (capture) {
    if (!motions.toolpath.openMemory() || !dprnt.openMemory()) {
      std::fputs("mbc: error: out of memory\n", stderr);
      return false;
    }
  } else {
    const std::string* failed = nullptr;
    if (!o.toolpathPath.empty() && !motions.toolpath.open(o.toolpathPath)) {
      failed = &o.toolpathPath;
    } else if (o.dprntPath.empty()) {
      dprnt.useStdout();
    } else if (!dprnt.open(o.dprntPath)) {
      failed = &o.dprntPath;
    }
    if (failed != nullptr) {
      std::fprintf(stderr, "mbc: error: cannot write '%s'\n", failed->c_str());
      return false;
    }
    if (!o.svgPath.empty()) {
      motions.svg.emplace(o.svgView);
    }
    if (!o.htmlPath.empty()) {
      if (toolpathPage().empty()) {
        std::fprintf(stderr, "mbc: error: %s\n", kNoPageReason);
        return false;
      }
      motions.html.emplace();
    }
  }
  const MotionTargets all{motions.toolpath.get() != nullptr ? &motions.toolpath
                                                            : nullptr,
                          motions.svg ? &*motions.svg : nullptr,
                          motions.html ? &*motions.html : nullptr};
  const MotionTargets threaded =
      capture ? MotionTargets{} : ToolpathThread::wanted(o.writerThread, all);
  motions.here = all.except(threaded);
  if (threaded.any()) {
    motions.writer.emplace(threaded);
    mbrt_set_output_settle(ctx, &MotionOutputs::settle, &motions);
  }
  if (all.any()) {
    mbrt_set_motion_sink(ctx, &MotionOutputs::write, &motions);
  }
  mbrt_set_print_sink(ctx, &OutputFile::writeText, &dprnt);
  return true;
}

} // namespace

std::string contextText(std::size_t (*get)(const mbrt_ctx*, char*, std::size_t),
                        const mbrt_ctx* ctx) {
  std::string out(get(ctx, nullptr, 0), '\0');
  get(ctx, out.data(), out.size() + 1);
  return out;
}

std::string clockText(double seconds) {
  const auto tenths = static_cast<long long>(std::llround(seconds * 10.0));
  const long long hours = tenths / 36000;
  const long long minutes = tenths / 600 % 60;
  const double rest = static_cast<double>(tenths % 600) / 10.0;
  return hours > 0 ? fmt::format("{}:{:02}:{:04.1f}", hours, minutes, rest)
                   : fmt::format("{}:{:04.1f}", minutes, rest);
}

mbrt_status presetAndPass(const RunOptions& o, mbrt_ctx* ctx) {
  for (auto [number, value] : o.presets) {
    if (mbrt_status st = mbrt_preset_var(ctx, number, value)) {
      return st;
    }
  }
  if (o.args.empty()) {
    return 0;
  }
  std::vector<mbrt_word> words;
  for (auto [letter, value] : o.args) {
    words.push_back({letter, MBRT_WORD_VALUE, value});
  }
  return mbrt_set_main_args(ctx, words.data(), words.size());
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now() - start)
      .count();
}

CtxPtr createContext(const RunOptions& o) {
  char err[512] = {0};
  mbrt_ctx* ctx =
      o.machinePath.empty()
          ? mbrt_create(nullptr, err, sizeof err)
          : mbrt_create_from_file(o.machinePath.c_str(), err, sizeof err);
  if (!ctx) {
    std::fprintf(stderr, "mbc: error: %s\n", err);
  }
  return CtxPtr(ctx);
}

int runSession(const RunOptions& o, mbrt_ctx* ctx, const std::string& mainName,
               const MainRun& engine, SessionLog& log,
               const PhaseTimes& phases) {
  std::FILE* text = log.text;
  MotionOutputs motions;
  OutputFile dprnt, gcode;

  // The sinks point into this session's outputs: none may outlive it.
  struct SinksOff {
    mbrt_ctx* ctx;

    ~SinksOff() {
      mbrt_set_motion_sink(ctx, nullptr, nullptr);
      mbrt_set_print_sink(ctx, nullptr, nullptr);
      mbrt_set_message_sink(ctx, nullptr, nullptr);
      mbrt_set_trace_sink(ctx, nullptr, nullptr);
      mbrt_set_gcode_sink(ctx, nullptr, nullptr);
      mbrt_set_output_settle(ctx, nullptr, nullptr);
    }
  } sinksOff{ctx};

  if (!openOutputs(o, ctx, motions, dprnt, log.capture) ||
      !openGcode(o, ctx, gcode)) {
    return 2;
  }
  mbrt_set_message_sink(ctx, &writeLog, text);
  if (o.trace) {
    mbrt_set_trace_sink(ctx, &writeLog, text);
  }
  mbrt_set_max_blocks(ctx, o.maxBlocks);
  mbrt_set_max_output(ctx, o.maxOutput);
  mbrt_set_block_skip(ctx, o.blockSkipMask);
  mbrt_start(ctx, mainName.c_str());
  std::string stateError;
  if (!o.statePath.empty() && !loadState(ctx, o.statePath, stateError)) {
    std::fprintf(stderr, "mbc: error: state file '%s': %s\n",
                 o.statePath.c_str(), stateError.c_str());
    return 2;
  }
  mbrt_status st = 0;
  const auto runStart = std::chrono::steady_clock::now();
  {
    const InterruptibleRun interruptible(ctx);
    st = presetAndPass(o, ctx);
    if (!st) {
      st = engine(ctx);
    }
  }
  // Every record of the run is written before anything is said of it.
  if (motions.writer) {
    motions.writer->finish();
  }
  const double runMs = millisecondsSince(runStart);
  if (st) {
    char report[4096];
    mbrt_alarm_report(ctx, report, sizeof report);
    std::fflush(stdout);
    std::fputs(report, text);
    log.alarm = std::string(report, std::strcspn(report, "\n"));
  }
  if (gcode.get() != nullptr) {
    OutputFile::writeText(&gcode, "%\n", 2);
  }
  // Every output is checked: a full disk must not pass for a complete run.
  bool written = true;
  const auto lost = [&written](const std::string& path) {
    const std::string shown =
        path == "-" ? "standard output" : "'" + path + "'";
    std::fprintf(stderr, "mbc: error: cannot write %s: %s\n", shown.c_str(),
                 std::strerror(errno));
    written = false;
  };
  for (OutputFile* out : {&motions.toolpath, &dprnt, &gcode}) {
    if (!out->finish()) {
      lost(out->path());
    }
  }
  if (!o.statePath.empty() && !saveState(ctx, o.statePath)) {
    lost(o.statePath);
  }
  const std::string title = pictureTitle(o, ctx, mainName, st);
  if (motions.svg && !replaceFile(o.svgPath, motions.svg->document(title))) {
    lost(o.svgPath);
  }
  if (motions.html && !replaceFile(o.htmlPath, motions.html->document(title))) {
    lost(o.htmlPath);
  }
  if (!o.varsOutPath.empty() && !writeVariables(ctx, o.varsOutPath)) {
    lost(o.varsOutPath);
  }
  if (log.capture) {
    log.toolpath = motions.toolpath.takeMemory();
    log.dprnt = dprnt.takeMemory();
    log.vars = variablesJson(ctx);
  }
  mbrt_get_stats(ctx, &log.stats);
  printSummary(log.stats, mainName, st != 0, text);
  if (o.time) {
    std::string times = "mbc: time:";
    for (const auto& [phase, ms] : phases) {
      times += fmt::format(" {} {:.3f} ms,", phase, ms);
    }
    const std::string threaded = motions.writer
                                     ? fmt::format(" ({} on a writer thread)",
                                                   motions.writer->madeText())
                                     : "";
    std::fprintf(text, "%s run %.3f ms%s\n", times.c_str(), runMs,
                 threaded.c_str());
  }
  if (const int sig = InterruptScope::signal()) {
    return 128 + sig; // as the shell reports a process the signal ended
  }
  if (!written) {
    return 2;
  }
  // A run the compiler got wrong is no alarm of the program's.
  return st == static_cast<mbrt_status>(AlarmId::InternalError) ? 4
         : st                                                   ? 3
                                                                : 0;
}

int runOnce(const RunOptions& o, const std::string& mainName,
            const MainRun& engine, const PhaseTimes& phases) {
  CtxPtr ctx = createContext(o);
  if (!ctx) {
    return 2;
  }
  const InterruptScope interrupts;
  SessionLog log;
  return runSession(o, ctx.get(), mainName, engine, log, phases);
}

} // namespace mbc::runner
