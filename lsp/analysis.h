// What the server knows of one open document: the frontend's reading of
// it, as `mbc check` reads a file (its programs, the programs they call
// from the search path, the semantic checks and the review's warnings),
// and the diagnostics to publish.
#pragma once

#include "frontend/diagnostics.h"

#include <memory>
#include <string>
#include <vector>

#include "lsp/program_index.h"
#include "toolchain/compile_unit.h"

namespace mbc::lsp {

/// How the workspace reads its programs: the folders programs are found
/// in, and what the machine profile (mbc.json's "machine", or the
/// initialization options) says of the input.
struct AnalysisSettings {
  std::vector<std::string> includeDirs;
  std::string machinePath; // the profile runs use, "" for the built-in one
  bool defaultMachine = true;
  char latheSystem = 0;
  bool inch = false;
  bool decimalPointInput = false;
};

struct Analysis {
  toolchain::CompiledUnit cu;          // its source 0 is the document
  std::vector<Diagnostic> diagnostics; // in file order, as shown
  std::vector<Severity> severities;    // of each, after the view
  std::string failure; // a called program's file that could not be read
  std::vector<std::string> files; // the workspace's files read with it
};

/// How the frontend reads the workspace's programs under `settings`.
toolchain::LoadOptions loadOptions(const AnalysisSettings& settings);

/// Reads `text` as the file at `path`, with the files of the workspace
/// that define the programs it calls (and those they call).
std::unique_ptr<Analysis> analyse(const std::string& path,
                                  const std::string& text,
                                  const AnalysisSettings& settings,
                                  const ProgramIndex& index);

} // namespace mbc::lsp
