// Reads the input files and the programs they call, parses and checks them,
// and prints diagnostics.
#include "toolchain/compile_unit.h"

#include "frontend/parser.h"
#include "frontend/sema.h"
#include <mbc/addresses.h>
#include <mbc/limits.h>
#include <mbc/read_file.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <utility>

#include "toolchain/alarm_ranges.h"
#include "toolchain/call_checks.h"
#include "toolchain/main_program.h"
#include "toolchain/program_search.h"
#include "toolchain/reach_box.h"

namespace mbc::toolchain {

namespace {

bool readInto(const std::string& path, DiagnosticEngine& diags,
              const ParseOptions& options, CompiledUnit& out,
              std::string& failure) {
  // "-" is standard input, as for cat and cc.
  const bool standardInput = path == "-";
  std::string text;
  if (int error = readFile(standardInput ? "/dev/stdin" : path, text)) {
    failure = "cannot read '" + path + "': " + std::strerror(error);
    return false;
  }
  std::uint32_t id =
      out.sources.add(standardInput ? "<stdin>" : path, std::move(text));
  parseFile(out.sources, id, diags, options, out.unit);
  return true;
}

/// Where called programs are looked for: the inputs' folders, then -I.
std::vector<std::string> searchDirs(const std::vector<std::string>& files,
                                    const std::vector<std::string>& include) {
  std::vector<std::string> dirs;
  for (const std::string& file : files) {
    std::string dir = std::filesystem::path(file).parent_path().string();
    dir = dir.empty() ? "." : dir;
    if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) {
      dirs.push_back(dir);
    }
  }
  dirs.insert(dirs.end(), include.begin(), include.end());
  return dirs;
}

/// A found file without an O number or name holds the program it is named
/// for, as a data server's file does.
void nameAnonymousProgram(Unit& unit, std::size_t first,
                          const CalledProgram& called) {
  for (std::size_t i = first; i < unit.programs.size(); ++i) {
    Program& p = unit.programs[i];
    if (p.number < 0 && p.name == "MAIN") {
      p.number = called.number;
      p.name = called.name;
      p.duplicate = false;
    }
  }
}

/// Adds the programs the unit calls but does not define, as long as the
/// search path has a file for one of them.
bool loadCalledPrograms(const std::vector<std::string>& files,
                        const LoadOptions& load, DiagnosticEngine& diags,
                        const ParseOptions& options, CompiledUnit& out,
                        std::string& failure) {
  const std::vector<std::string> dirs = searchDirs(files, load.includeDirs);
  std::set<std::string> read(files.begin(), files.end());
  for (bool added = true; added;) {
    added = false;
    for (const CalledProgram& called : missingCalledPrograms(out.unit)) {
      const std::optional<std::string> path = findProgramFile(called, dirs);
      if (!path || !read.insert(*path).second) {
        continue;
      }
      const std::size_t first = out.unit.programs.size();
      if (!readInto(*path, diags, options, out, failure)) {
        return false;
      }
      nameAnonymousProgram(out.unit, first, called);
      added = true;
    }
  }
  return true;
}

} // namespace

bool parseInputs(const std::vector<SourceText>& texts,
                 const std::vector<std::string>& files, const LoadOptions& load,
                 CompiledUnit& out, DiagnosticEngine& diags,
                 std::string& failure) {
  ParseOptions options;
  options.checkWarnings = load.checkWarnings;
  options.latheSystem = load.latheSystem;
  options.inch = load.inch;
  options.decimalPointInput = load.decimalPointInput;
  options.stopAtErrorLimit = load.errors == ErrorMode::Refuse;
  for (const SourceText& input : texts) {
    const std::uint32_t id = out.sources.add(input.name, input.text);
    parseFile(out.sources, id, diags, options, out.unit);
  }
  for (const std::string& path : files) {
    if (!readInto(path, diags, options, out, failure)) {
      return false;
    }
  }
  if (!loadCalledPrograms(files, load, diags, options, out, failure)) {
    return false;
  }
  SemaOptions sema{load.defaultMachine, load.latheSystem, load.checkWarnings};
  if (load.alarmRanges) {
    sema.argumentProgram = findMain(out.unit, load.alarmRanges->mainProgram);
    IjkSets sets;
    for (const ArgumentRange& arg : load.alarmRanges->args) {
      const int local = nextArgumentLocal(arg.letter, sets);
      if (local >= 1 && local <= kLocalCount) {
        sema.argumentLocals |= std::uint64_t{1} << (local - 1);
      }
    }
  }
  checkUnit(out.unit, diags, sema);
  if (load.checkWarnings && diags.totalErrors() == 0) {
    checkCallsAgainstCallees(out, diags);
    if (load.alarmRanges) {
      UnitRanges ranges;
      if (!ranges.build(out, *load.alarmRanges, failure)) {
        out.blocksThatMayAlarm = -1;
        return false;
      }
      out.blocksThatMayAlarm = checkAlarmRanges(out, ranges, diags);
      if (load.machine) {
        const Reach reach = checkReach(out, ranges, *load.machine, diags);
        out.strokeFindings = reach.findings;
        out.reachDecided = reach.decided;
        for (const ir::Range& r : reach.box) {
          out.reachBox.emplace_back(r.lo, r.hi);
        }
      }
    }
  }
  return true;
}

bool loadUnit(const std::vector<std::string>& files, const LoadOptions& load,
              CompiledUnit& out) {
  DiagnosticEngine diags(out.sources);
  std::string failure;
  if (!parseInputs({}, files, load, out, diags, failure)) {
    std::fprintf(stderr, "mbc: error: %s\n", failure.c_str());
    return false;
  }
  const DiagnosticOutput& output = load.diagnostics;
  const DiagnosticView view{load.errors, output.warnings, output.disabled};
  const bool text = output.format == DiagnosticFormat::Text;
  std::fputs(text ? renderDiagnostics(diags, view, output.color).c_str()
             : output.format == DiagnosticFormat::Json
                 ? diagnosticsJson(diags, view).c_str()
                 : diagnosticsSarif(diags, view).c_str(),
             stderr);
  // -Werror: a warning refuses the input, whatever the mode; errors under
  // ErrorMode::Alarm are their blocks' alarms.
  const int errors = shownErrorCount(diags, view) -
                     (load.errors == ErrorMode::Alarm ? diags.errorCount() : 0);
  if (errors > 0) {
    if (text) {
      std::fprintf(stderr, "%d error%s generated.\n", errors,
                   errors == 1 ? "" : "s");
    }
    return false;
  }
  if (load.errors == ErrorMode::Alarm && diags.totalErrors() > 0 && text) {
    std::fprintf(stderr,
                 "mbc: warning: %d error%s in the input: each block that has "
                 "one raises its alarm if the run reaches it (--strict "
                 "refuses the input)\n",
                 diags.totalErrors(), diags.totalErrors() == 1 ? "" : "s");
  }
  return true;
}

} // namespace mbc::toolchain
