// A run of one program of a document, for its code lens: the document's
// text as the editor holds it, with the workspace's files that define the
// programs it calls, on the workspace's machine profile, run by the
// interpreter (the engines agree; the interpreter needs no code generated)
// within a budget of blocks, so that a loop that never ends costs the
// editor a moment rather than the server.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lsp/analysis.h"

namespace mbc::lsp {

/// Blocks a lens's run may execute (a fraction of a second in the
/// interpreter) before it stops with MBC0002.
inline constexpr std::uint64_t kRunBlockBudget = 5'000'000;

/// The command a lens runs: the run's --html view, opened in a browser.
inline constexpr const char* kShowRunCommand = "mbc.showRun";

struct RunInput {
  std::string path; // the document's, for diagnostics and alarm reports
  std::string text;
  std::vector<std::string> files; // the workspace's, as the analysis read
  AnalysisSettings settings;
  std::string program; // the main program, by name
  std::uint64_t blockBudget = kRunBlockBudget;
};

struct RunSummary {
  std::string failure; // why it could not run ("" when it ran)
  std::uint64_t blocks = 0;
  std::uint64_t moves = 0;
  double cycleTime = 0;     // seconds
  std::uint64_t budget = 0; // the blocks it might run
  bool budgetSpent = false; // it stopped after them
  std::string alarmCode;    // "" when the run ended without one
  std::string alarmMessage;
  std::string alarmFile; // as the run names it: the document is `path`
  int alarmLine = 0;
};

/// Runs the program; with `htmlPath`, writes the --html view of the run.
RunSummary runProgram(const RunInput& input, const std::string& htmlPath);

/// The lens's text: "1234 moves · 2:05.3 · ended", or the alarm and where.
std::string lensTitle(const RunSummary& run, const std::string& path);

} // namespace mbc::lsp
