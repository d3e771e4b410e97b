// A run for a code lens (see program_runs.h).
#include "lsp/program_runs.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "runner/html_page.h"
#include "runner/run_session.h"
#include "toolchain/prepared_program.h"

namespace mbc::lsp {

namespace {

/// The run's report and summary lines: the editor shows the lens instead.
struct NullLog {
  std::FILE* file = std::fopen("/dev/null", "w");

  ~NullLog() {
    if (file != nullptr) {
      std::fclose(file);
    }
  }
};

} // namespace

RunSummary runProgram(const RunInput& input, const std::string& htmlPath) {
  RunSummary out;
  if (!htmlPath.empty() && runner::toolpathPage().empty()) {
    out.failure = runner::kNoPageReason;
    return out;
  }
  toolchain::Request request;
  request.load = loadOptions(input.settings);
  request.engine = toolchain::Engine::Interp;
  request.mainProgram = input.program;
  toolchain::PreparedProgram prepared;
  DiagnosticEngine diags(prepared.sources());
  runner::PhaseTimes phases;
  if (!prepared.parse({toolchain::SourceText{input.path, input.text}},
                      input.files, request.load, diags, out.failure)) {
    return out;
  }
  if (prepared.build(request, phases, out.failure) != 0) {
    return out;
  }
  runner::RunOptions options;
  options.machinePath = input.settings.machinePath;
  options.maxBlocks = input.blockBudget;
  options.htmlPath = htmlPath;
  // No toolpath is kept, and DPRNT goes nowhere: a lens's run of a
  // million moves costs no memory.
  options.dprntPath = "/dev/null";
  char error[512] = "";
  runner::CtxPtr ctx(options.machinePath.empty()
                         ? mbrt_create(nullptr, error, sizeof error)
                         : mbrt_create_from_file(options.machinePath.c_str(),
                                                 error, sizeof error));
  const NullLog log;
  if (!ctx || log.file == nullptr) {
    out.failure = ctx ? "/dev/null cannot be opened" : error;
    return out;
  }
  runner::SessionLog session;
  session.text = log.file;
  const int status = runner::runSession(
      options, ctx.get(), prepared.mainName(),
      [&prepared](mbrt_ctx* c) { return prepared.run(c); }, session);
  if (status == 2) {
    out.failure = htmlPath.empty() ? "an output could not be kept"
                                   : "cannot write " + htmlPath;
  }
  out.blocks = session.stats.blocks;
  out.moves = session.stats.moves;
  out.cycleTime = session.stats.cycle_time;
  out.budget = input.blockBudget;
  out.budgetSpent = mbrt_alarm(ctx.get()) == MBRT_ALARM_ExecutionLimit;
  if (mbrt_alarm(ctx.get()) != 0 && !out.budgetSpent) {
    out.alarmCode = runner::contextText(mbrt_alarm_code, ctx.get());
    out.alarmMessage = runner::contextText(mbrt_alarm_message, ctx.get());
    const char* file = mbrt_alarm_file(ctx.get());
    out.alarmFile = file != nullptr ? file : "";
    out.alarmLine = mbrt_alarm_line(ctx.get());
  }
  return out;
}

std::string lensTitle(const RunSummary& run, const std::string& path) {
  if (!run.failure.empty()) {
    return "does not run: " + run.failure;
  }
  std::string title =
      fmt::format("{} move{} \u00b7 {}", run.moves, run.moves == 1 ? "" : "s",
                  runner::clockText(run.cycleTime));
  if (run.budgetSpent) {
    return title + fmt::format(" \u00b7 stopped after {} blocks (a loop that "
                               "does not end?)",
                               run.budget);
  }
  if (run.alarmCode.empty()) {
    return title + " \u00b7 ends";
  }
  title += fmt::format(" \u00b7 alarm {} {}", run.alarmCode, run.alarmMessage);
  if (run.alarmLine > 0) {
    title += run.alarmFile == path
                 ? fmt::format(" (line {})", run.alarmLine)
                 : fmt::format(
                       " ({}:{})",
                       std::filesystem::path(run.alarmFile).filename().string(),
                       run.alarmLine);
  }
  return title;
}

} // namespace mbc::lsp
