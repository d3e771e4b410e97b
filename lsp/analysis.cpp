// A document's analysis (see analysis.h).
#include "lsp/analysis.h"

#include <algorithm>
#include <set>

#include "toolchain/program_search.h"

namespace mbc::lsp {

namespace {

/// A call chain is followed this many files deep through the index.
constexpr int kMaxRounds = 8;

std::unique_ptr<Analysis> read(const std::string& path, const std::string& text,
                               const std::vector<std::string>& files,
                               const AnalysisSettings& settings) {
  auto out = std::make_unique<Analysis>();
  out->files = files;
  toolchain::LoadOptions load = loadOptions(settings);
  load.checkWarnings = true;
  DiagnosticEngine diags(out->cu.sources);
  toolchain::parseInputs({toolchain::SourceText{path, text}}, files, load,
                         out->cu, diags, out->failure);
  // Errors stay errors in the editor: ErrorMode::Refuse's view.
  for (const ShownDiagnostic& shown : shownDiagnostics(diags, {})) {
    out->diagnostics.push_back(*shown.diagnostic);
    out->severities.push_back(shown.severity);
  }
  return out;
}

} // namespace

toolchain::LoadOptions loadOptions(const AnalysisSettings& settings) {
  toolchain::LoadOptions load;
  load.defaultMachine = settings.defaultMachine;
  load.latheSystem = settings.latheSystem;
  load.inch = settings.inch;
  load.decimalPointInput = settings.decimalPointInput;
  // Every error is reported, each block with one alarming as a run would.
  load.errors = ErrorMode::Alarm;
  load.includeDirs = settings.includeDirs;
  return load;
}

std::unique_ptr<Analysis> analyse(const std::string& path,
                                  const std::string& text,
                                  const AnalysisSettings& settings,
                                  const ProgramIndex& index) {
  std::vector<std::string> files;
  std::unique_ptr<Analysis> out = read(path, text, files, settings);
  for (int round = 0; round < kMaxRounds; ++round) {
    std::set<std::string> more;
    for (const CalledProgram& program :
         toolchain::missingCalledPrograms(out->cu.unit)) {
      const std::optional<std::string> file = index.fileOf(program);
      if (file && *file != path &&
          std::find(files.begin(), files.end(), *file) == files.end()) {
        more.insert(*file);
      }
    }
    if (more.empty()) {
      break;
    }
    files.insert(files.end(), more.begin(), more.end());
    out = read(path, text, files, settings);
  }
  return out;
}

} // namespace mbc::lsp
