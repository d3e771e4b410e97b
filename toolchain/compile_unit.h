// Reading, parsing and checking the input files: the front half shared by
// every mbc command.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"
#include "frontend/source.h"

#include <optional>
#include <string>
#include <vector>

#include "toolchain/argument_ranges.h"
#include "toolchain/diagnostic_formats.h"
#include "toolchain/machine_facts.h"

namespace mbc::toolchain {

struct CompiledUnit {
  SourceManager sources;
  Unit unit;
  // mbc check --arg/--prove: the blocks the range analysis finds may
  // alarm (-1 when it could not run).
  int blocksThatMayAlarm = 0;
  // mbc check --arg/--prove --machine: where the tool may go, per axis in
  // machine coordinates, and the blocks that may pass a stroke's end or
  // where the analysis lost the tool (reach_box.h).
  std::vector<std::pair<double, double>> reachBox;
  bool reachDecided = true;
  int strokeFindings = 0;
};

/// How loadUnit reads the input.
struct LoadOptions {
  bool checkWarnings = false; // mbc check: the warnings only a review needs
  // The input runs on the built-in default machine: variables only a
  // profile has get a warning. False with --machine, and for compile and
  // build, whose code learns its machine when it runs.
  bool defaultMachine = true;
  char latheSystem = 0; // the profile's lathe G code system, 0: a mill
  bool inch = false;    // the profile's unit at power-on is the inch
  bool decimalPointInput = false; // the profile's 3401#0 DPI
  ErrorMode errors = ErrorMode::Refuse;
  std::vector<std::string> includeDirs; // -I: more places to find programs
  DiagnosticOutput diagnostics;
  // mbc check --arg/--prove: the main program and its argument ranges.
  std::optional<AlarmRangeRequest> alarmRanges;
  // ... and the machine of --machine, where the tool goes on it.
  std::optional<MachineFacts> machine;
};

/// An input given as text rather than a file (the Python package's
/// sources), named for diagnostics and alarm reports.
struct SourceText {
  std::string name;
  std::string text;
};

/// Parses and checks the texts, the files and the programs they call that
/// none of them defines (as loadUnit), leaving the diagnostics in `diags`
/// (made for out.sources) unprinted. False when a file could not be read,
/// with the reason in `failure`; errors in the input are only diagnostics.
bool parseInputs(const std::vector<SourceText>& texts,
                 const std::vector<std::string>& files, const LoadOptions& load,
                 CompiledUnit& out, DiagnosticEngine& diags,
                 std::string& failure);

/// Loads and checks the files, and the programs they call that none of them
/// defines, from the files' folders and the -I folders (program_search.h).
/// Diagnostics go to standard error. Returns false when a file could not be
/// read, or when there were errors and the mode is ErrorMode::Refuse; under
/// ErrorMode::Alarm errors print as warnings and each block that has one
/// raises its alarm when it runs.
bool loadUnit(const std::vector<std::string>& files, const LoadOptions& options,
              CompiledUnit& out);

} // namespace mbc::toolchain
