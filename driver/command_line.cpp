// The commands and options of mbc, read with CLI11 (Debian's libcli11-dev):
// it gives the help texts, --name=value and -nV forms and the checks of
// option arity; mbc adds what CLI11 leaves to its users: its own messages
// for bad values (addValueOption), "did you mean" and the commands an
// option belongs to (unknown_arguments.h).
#include "driver/command_line.h"

#include "driver/unknown_arguments.h"
#include "driver/version_text.h"
#include "ir/pass_manager.h"
#include <mbc/addresses.h>

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string_view>
#include <unistd.h>

#include "runner/help_formatter.h"
#include "toolchain/closest_match.h"

namespace mbc::driver {

namespace {

// Holds what the options write into while the line is read.
struct Reader {
  Options o;
  std::string error; // the first bad value's message
  std::string helpTopic;
  std::string color = "auto"; // --color=auto|always|never
};

std::string stored(std::string& field, const std::string& value) {
  field = value;
  return "";
}

void addFlag(CLI::App& cmd, const std::string& name, bool& field,
             const std::string& help, const std::string& group) {
  cmd.add_flag_callback(
         name, [&field] { field = true; }, help)
      ->group(group);
}

// -W: error, no-error, FLAG or no-FLAG of a warning (diagnostic_kinds.def).
std::string readWarningOption(Reader& r, const std::string& v) {
  if (v == "error" || v == "no-error") {
    r.o.diagnostics.warnings =
        v == "error" ? WarningMode::Error : WarningMode::Show;
    return "";
  }
  const bool off = v.starts_with("no-");
  const std::string flag = off ? v.substr(3) : v;
  if (const std::optional<DiagKind> kind = warningNamed(flag)) {
    if (off) {
      r.o.diagnostics.disabled.insert(*kind);
    } else {
      r.o.diagnostics.disabled.erase(*kind);
    }
    return "";
  }
  std::vector<std::string> known;
  for (std::string_view f : warningFlags()) {
    known.emplace_back(f);
  }
  const std::string near = toolchain::closestMatch(flag, known);
  return fmt::format("unknown warning option '-W{}'{}", v,
                     near.empty() ? fmt::format(" (docs/check.md lists mbc's "
                                                "warnings)")
                                  : fmt::format("; did you mean '-W{}{}'?",
                                                off ? "no-" : "", near));
}

// How the diagnostics of the input come out.
void addDiagnosticOptions(CLI::App& cmd, Reader& r) {
  const std::string group = "Diagnostics";
  runner::addValueOption(
      cmd, "--diagnostics-format", "text|json|sarif",
      "print the diagnostics as clang does (default), as one line "
      "of JSON or as a SARIF 2.1.0 log",
      r.error,
      [&r](const std::string& v) -> std::string {
        toolchain::DiagnosticFormat& f = r.o.diagnostics.format;
        if (v == "text" || v == "json" || v == "sarif") {
          f = v == "text"   ? toolchain::DiagnosticFormat::Text
              : v == "json" ? toolchain::DiagnosticFormat::Json
                            : toolchain::DiagnosticFormat::Sarif;
          return "";
        }
        return fmt::format("unknown diagnostics format '{}' (text, "
                           "json or sarif)",
                           v);
      })
      ->group(group);
  const std::string colorHelp =
      "colour the diagnostics: on a terminal unless NO_COLOR is set (auto, "
      "the default), always (--color alone) or never";
  cmd.add_flag("--color{always}", colorHelp)
      ->type_name("[=WHEN]")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->each([&r](const std::string& v) {
        if (v != "auto" && v != "always" && v != "never") {
          if (r.error.empty()) {
            r.error = fmt::format(
                "--color expects auto, always or never, got '{}'", v);
          }
          return;
        }
        r.color = v;
      })
      ->group(group);
  cmd.add_flag_callback(
         "-w", [&r] { r.o.diagnostics.warnings = WarningMode::Hide; },
         std::string("show no warnings"))
      ->group(group);
  runner::addValueOption(
      cmd, "-W", "FLAG",
      "-Wno-FLAG hides one kind of warning and -WFLAG shows it again "
      "(docs/check.md lists them); -Werror makes every warning shown an "
      "error (the input is refused), -Wno-error undoes it",
      r.error, [&r](const std::string& v) { return readWarningOption(r, v); })
      ->group(group);
}

// --color=auto: on a terminal that shows colours, unless the user said
// NO_COLOR (no-color.org) in the environment.
bool colorWanted(const std::string& when) {
  if (when != "auto") {
    return when == "always";
  }
  const char* noColor = std::getenv("NO_COLOR");
  const char* term = std::getenv("TERM");
  return isatty(STDERR_FILENO) != 0 &&
         (noColor == nullptr || *noColor == '\0') &&
         (term == nullptr || std::string_view(term) != "dumb");
}

// FILE... and what decides how they are read.
void addInputs(CLI::App& cmd, Reader& r, bool noStrict) {
  cmd.add_option("FILE", r.o.files,
                 "the programs, and the files of the programs they call "
                 "('-': standard input)")
      ->type_name("");
  runner::addValueOption(cmd, "-I", "DIR",
                         "look for called programs in DIR too (repeatable)",
                         r.error,
                         [&r](const std::string& v) {
                           r.o.includeDirs.push_back(v);
                           return "";
                         })
      ->group("Input");
  cmd.add_flag_callback(
         "--strict", [&r] { r.o.strict = true; },
         std::string("refuse an input with errors"))
      ->group("Input");
  addDiagnosticOptions(cmd, r);
  if (noStrict) {
    cmd.add_flag_callback(
           "--no-strict", [&r] { r.o.strict = false; },
           std::string("accept an input with errors: each block that has "
                       "one raises its alarm when it runs"))
        ->group("Input");
  }
}

// -O as clang reads it: -O0 to -O3, -O (= -O1), -Os and -Oz (-O2 making
// code smaller), -Og (= -O1), -O4 and above (= -O3).
std::string setOptLevel(Options& o, const std::string& level) {
  o.sizeLevel = 0;
  if (level == "s" || level == "z") {
    o.optLevel = 2;
    o.sizeLevel = level == "s" ? 1 : 2;
  } else if (level == "g") {
    o.optLevel = 1;
  } else if (!level.empty() &&
             level.find_first_not_of("0123456789") == std::string::npos &&
             level.size() < 4) {
    o.optLevel = std::min(std::stoi(level), 3);
  } else {
    return fmt::format("invalid optimisation level '-O{}' (-O0 to -O3, -O, "
                       "-Os, -Oz or -Og)",
                       level);
  }
  return "";
}

void addCodeOptions(CLI::App& cmd, Reader& r) {
  runner::addValueOption(
      cmd, "-O", "LEVEL",
      "optimise: -O0 to -O3 (default -O2), -O (-O1), -Os and -Oz "
      "(smaller code), -Og (-O1)",
      r.error, [&r](const std::string& v) { return setOptLevel(r.o, v); })
      ->group("Code generation");
  addFlag(cmd, "-g", r.o.debugInfo,
          "debug information: the code's lines are the program's blocks",
          "Code generation");
}

void addPassOptions(CLI::App& cmd, Reader& r) {
  const std::string group = "IR passes";
  addFlag(cmd, "--no-opt", r.o.noOpt, "run none of mbc's IR passes", group);
  runner::addValueOption(
      cmd, "--disable-pass", "NAME",
      "skip one IR pass (repeatable): " + ir::passNameList(), r.error,
      [&r](const std::string& v) -> std::string {
        if (!ir::isPassName(v)) {
          return fmt::format("unknown pass '{}' (passes: {})", v,
                             ir::passNameList());
        }
        r.o.disabledPasses.push_back(v);
        return "";
      })
      ->group(group);
  addFlag(cmd, "--verify-each", r.o.verifyEach,
          "verify the IR after every pass", group);
}

void addEngineOptions(CLI::App& cmd, Reader& r) {
  runner::addValueOption(cmd, "--engine", toolchain::engineList("|", "|"),
                         "what runs the program: native code (default), the "
                         "interpreter of the source or the IR evaluator",
                         r.error,
                         [&r](const std::string& v) -> std::string {
                           const std::optional<toolchain::Engine> engine =
                               toolchain::engineNamed(v);
                           if (!engine) {
                             return fmt::format(
                                 "unknown engine '{}' ({})", v,
                                 toolchain::engineList(", ", " or "));
                           }
                           r.o.engine = *engine;
                           return "";
                         })
      ->group("Run");
  addFlag(cmd, "--no-cache", r.o.noCache,
          "compile again rather than load the cached code", "Run");
}

std::string setLanguage(Options& o, const std::string& v) {
  if (v != "nc" && v != "mbir") {
    return fmt::format("unknown input language '{}' (nc or mbir)", v);
  }
  o.language = v;
  return "";
}

void addOutputFile(CLI::App& cmd, Reader& r, const std::string& help) {
  runner::addValueOption(
      cmd, "-o", "PATH", help, r.error,
      [&r](const std::string& v) { return stored(r.o.outputPath, v); })
      ->group("Output");
}

void addCpu(CLI::App& cmd, Reader& r) {
  runner::addValueOption(
      cmd, "--cpu", "NAME",
      "the CPU to compile for: 'native' (this machine) or an LLVM "
      "CPU name (default: the architecture's generic one)",
      r.error, [&r](const std::string& v) { return stored(r.o.cpu, v); })
      ->group("Code generation");
}

bool isCIdentifier(const std::string& s) {
  if (s.empty() || (s[0] >= '0' && s[0] <= '9')) {
    return false;
  }
  return std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
           (c >= '0' && c <= '9') || c == '_';
  });
}

// What run and batch share after their own options.
void addRunningOptions(CLI::App& cmd, Reader& r, runner::RunOutputs outputs) {
  addEngineOptions(cmd, r);
  runner::addRunOptions(cmd, r.o.run, r.error, outputs);
  addCodeOptions(cmd, r);
  addPassOptions(cmd, r);
}

void defineRun(CLI::App& app, Reader& r) {
  CLI::App* cmd = app.add_subcommand(
      "run", "Run a program: its toolpath, DPRNT output and variables");
  addInputs(*cmd, r, true);
  addRunningOptions(*cmd, r, runner::RunOutputs::Single);
}

void defineBatch(CLI::App& app, Reader& r) {
  CLI::App* cmd = app.add_subcommand(
      "batch", "Run a program once per row of a table of arguments");
  addInputs(*cmd, r, true);
  const std::string group = "Batch";
  runner::addValueOption(
      *cmd, "--params", "TABLE.csv",
      "the table: a column per G65 argument letter or #N, "
      "optionally 'id'",
      r.error, [&r](const std::string& v) { return stored(r.o.paramsPath, v); })
      ->group(group);
  runner::addValueOption(
      *cmd, "--out", "DIR",
      "write each row's toolpath, DPRNT, variables and log here", r.error,
      [&r](const std::string& v) { return stored(r.o.outDir, v); })
      ->group(group);
  runner::addValueOption(*cmd, "-j,--jobs", "N",
                         "run N rows at once (default: one per core)", r.error,
                         [&r](const std::string& v) -> std::string {
                           double jobs = 0;
                           if (!runner::parseNumber(v, jobs) || jobs < 1 ||
                               jobs > 256 || jobs != static_cast<int>(jobs)) {
                             return fmt::format(
                                 "-j expects a number of threads from "
                                 "1 to 256, got '{}'",
                                 v);
                           }
                           r.o.jobs = static_cast<int>(jobs);
                           return "";
                         })
      ->group(group);
  runner::addValueOption(
      *cmd, "--shard", "I/N", "run only the I-th of N equal parts of the table",
      r.error, [&r](const std::string& v) { return stored(r.o.shard, v); })
      ->group(group);
  runner::addValueOption(
      *cmd, "--column", "NAME=TARGET",
      "read the table's column NAME as the argument letter, #N "
      "or id TARGET; NAME= ignores the column (repeatable)",
      r.error,
      [&r](const std::string& v) -> std::string {
        const std::size_t eq = v.find('=');
        if (eq == 0 || eq == std::string::npos) {
          return fmt::format("--column expects NAME=TARGET (such "
                             "as depth=Z), got '{}'",
                             v);
        }
        r.o.columnMap.emplace_back(v.substr(0, eq), v.substr(eq + 1));
        return "";
      })
      ->group(group);
  addFlag(*cmd, "--combined", r.o.combined,
          "write all rows' results into one JSONL file", group);
  addFlag(*cmd, "--resume", r.o.resume,
          "keep the rows an earlier batch finished in --out and run the "
          "others",
          group);
  addRunningOptions(*cmd, r, runner::RunOutputs::None);
}

/// `X=0..20` or `R=5`: a letter and the range of its value.
std::optional<toolchain::ArgumentRange> argumentRange(std::string_view text) {
  if (text.size() < 3 || text[1] != '=') {
    return std::nullopt;
  }
  toolchain::ArgumentRange range;
  range.letter =
      static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  const std::string_view value = text.substr(2);
  const std::size_t dots = value.find("..");
  if (range.letter < 'A' || range.letter > 'Z' ||
      !runner::parseNumber(value.substr(0, dots), range.lo) ||
      !runner::parseNumber(
          dots == std::string_view::npos ? value : value.substr(dots + 2),
          range.hi) ||
      range.lo > range.hi) {
    return std::nullopt;
  }
  return range;
}

void defineCheck(CLI::App& app, Reader& r) {
  CLI::App* cmd = app.add_subcommand(
      "check", "Report the errors and warnings of a program, run nothing");
  addInputs(*cmd, r, false);
  runner::addValueOption(
      *cmd, "--machine", "PATH", "check against this machine profile (JSON)",
      r.error,
      [&r](const std::string& v) { return stored(r.o.run.machinePath, v); })
      ->group("Input");
  const std::string group = "Alarms over argument ranges";
  runner::addValueOption(
      *cmd, "--main", "O1234|<NAME>",
      "the program the ranges are for (default: the first one in the input)",
      r.error,
      [&r](const std::string& v) { return stored(r.o.run.mainProgram, v); })
      ->group(group);
  runner::addValueOption(
      *cmd, "--arg", "X=LO..HI",
      "a G65 argument of the main program and the range of its value (or "
      "one value, X=5); the blocks that may alarm over the ranges are "
      "reported (repeatable)",
      r.error,
      [&r](const std::string& v) {
        const std::optional<toolchain::ArgumentRange> range = argumentRange(v);
        if (!range) {
          return fmt::format(
              "--arg expects LETTER=LO..HI or LETTER=VALUE, got '{}'", v);
        }
        IjkSets fresh;
        if (nextArgumentLocal(range->letter, fresh) < 1) {
          // As `mbc run --arg` refuses it (PS0125).
          return fmt::format("--arg {}: {} cannot be a macro argument (G, L, "
                             "N, O and P are not)",
                             v, range->letter);
        }
        r.o.argRanges.push_back(*range);
        return std::string();
      })
      ->group(group);
  addFlag(*cmd, "--prove", r.o.prove,
          "exit 0 only when the range analysis shows that no block can raise "
          "an alarm it decides (docs/check.md)",
          group);
}

void defineEmitIr(CLI::App& app, Reader& r) {
  CLI::App* cmd = app.add_subcommand(
      "emit-ir", "Print the program's IR after mbc's passes");
  addInputs(*cmd, r, true);
  runner::addValueOption(
      *cmd, "-x", "nc|mbir",
      "the input's language: programs (default) or IR text", r.error,
      [&r](const std::string& v) { return setLanguage(r.o, v); })
      ->group("Input");
  addFlag(*cmd, "--trace", r.o.run.trace,
          "lower with the trace statements of --trace runs", "IR passes");
  addPassOptions(*cmd, r);
}

void defineCompile(CLI::App& app, Reader& r) {
  CLI::App* cmd = app.add_subcommand(
      "compile", "Compile programs to an object file or a shared library");
  addInputs(*cmd, r, true);
  runner::addValueOption(
      *cmd, "-x", "nc|mbir",
      "the input's language: programs (default) or IR text", r.error,
      [&r](const std::string& v) { return setLanguage(r.o, v); })
      ->group("Input");
  addOutputFile(*cmd, r, "the file to write ('-': standard output)");
  runner::addValueOption(
      *cmd, "--header", "PATH",
      "write a C header declaring the entry points too", r.error,
      [&r](const std::string& v) { return stored(r.o.headerPath, v); })
      ->group("Output");
  runner::addValueOption(
      *cmd, "--emit", "ir|llvm|asm|obj", "what to write (default: obj)",
      r.error,
      [&r](const std::string& v) -> std::string {
        if (v != "obj" && v != "asm" && v != "llvm" && v != "ir") {
          return fmt::format("unknown --emit '{}' (ir, llvm, asm or obj)", v);
        }
        r.o.emit = v;
        return "";
      })
      ->group("Output");
  runner::addValueOption(
      *cmd, "--table", "NAME", "the name of the program table (a C identifier)",
      r.error,
      [&r](const std::string& v) -> std::string {
        if (!isCIdentifier(v)) {
          return fmt::format("--table '{}' is not a C identifier", v);
        }
        r.o.tableName = v;
        return "";
      })
      ->group("Output");
  addFlag(*cmd, "--shared", r.o.shared,
          "write a shared library with the runtime in it", "Output");
  // As with cc -c: compile only, which mbc compile always does.
  cmd->add_flag_callback(
         "-c", [] {}, std::string("compile only (what compile always does)"))
      ->group("Output");
  addFlag(*cmd, "-v", r.o.verbose, "print the link command (--shared)",
          "Output");
  addCpu(*cmd, r);
  addCodeOptions(*cmd, r);
  addPassOptions(*cmd, r);
}

void defineBuild(CLI::App& app, Reader& r) {
  CLI::App* cmd = app.add_subcommand(
      "build", "Build an executable that runs the programs (it takes the "
               "options of mbc run)");
  addInputs(*cmd, r, true);
  addOutputFile(*cmd, r, "the executable to write");
  addFlag(*cmd, "-v", r.o.verbose, "print the link command", "Output");
  addCpu(*cmd, r);
  addCodeOptions(*cmd, r);
  addPassOptions(*cmd, r);
}

void defineLsp(CLI::App& app) {
  app.add_subcommand("lsp", "Serve an editor: the Language Server Protocol on "
                            "standard input and output (docs/editors.md)");
}

void defineHelp(CLI::App& app, Reader& r) {
  CLI::App* cmd =
      app.add_subcommand("help", "Show the help of mbc or of one command");
  cmd->add_option("command", r.helpTopic, "the command")->type_name("COMMAND");
}

// The combinations of options that make no sense.
std::string checkCombinations(const Options& o) {
  const bool producesFile = o.command == "compile" || o.command == "build";
  if (o.command == "lsp") {
    return ""; // its input is the editor's messages
  }
  if (o.files.empty()) {
    return "no input file";
  }
  if (std::count(o.files.begin(), o.files.end(), "-") > 1) {
    return "standard input ('-') can be read only once";
  }
  if (o.language == "mbir" && o.command == "compile" && o.files.size() > 1) {
    return "-x mbir reads one IR file";
  }
  if (producesFile && o.outputPath.empty()) {
    return fmt::format("mbc {} needs -o OUTPUT", o.command);
  }
  if (o.shared && o.emit != "obj") {
    return fmt::format("--shared writes a shared library, not --emit={}",
                       o.emit);
  }
  if (o.shared && o.outputPath == "-") {
    return "mbc compile --shared needs -o FILE.so";
  }
  if (o.command == "batch" && (o.paramsPath.empty() || o.outDir.empty())) {
    return "mbc batch needs --params TABLE.csv and --out DIR";
  }
  return runner::runOptionsProblem(o.run);
}

int usageError(const std::string& message, const std::string& command) {
  std::fprintf(stderr, "mbc: error: %s\n", message.c_str());
  if (command.empty()) {
    std::fputs("mbc: note: 'mbc --help' lists the commands\n", stderr);
  } else {
    std::fprintf(stderr, "mbc: note: 'mbc %s --help' lists its options\n",
                 command.c_str());
  }
  return 2;
}

// The first argument of `command` that is no option of it, if any.
std::string unknownArgument(const CLI::App& root, const CLI::App& command) {
  for (const std::string& arg : command.remaining()) {
    if (arg.starts_with("-") && arg != "-") {
      return unknownOptionMessage(root, command, arg);
    }
    return fmt::format("unexpected argument '{}' for mbc {}", arg,
                       command.get_name());
  }
  return "";
}

CommandLine helpFor(const CLI::App& app, const std::string& topic) {
  if (topic.empty()) {
    std::cout << app.help();
    return {};
  }
  for (const CLI::App* cmd : app.get_subcommands({})) {
    if (cmd->get_name() == topic) {
      std::cout << cmd->help();
      return {};
    }
  }
  return {std::nullopt, usageError(unknownCommandMessage(app, topic), "")};
}

// CLI11's arguments: the line reversed, -O written -O1 (clang's -O takes
// no separate value).
std::vector<std::string> cliArguments(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = argc - 1; i >= 1; --i) {
    const std::string arg = argv[i];
    args.push_back(arg == "-O" ? "-O1" : arg);
  }
  return args;
}

} // namespace

CommandLine parseCommandLine(int argc, char** argv) {
  Reader r;
  CLI::App app("mbc compiles FANUC Custom Macro B programs to native code "
               "and runs them.",
               "mbc");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag(
      "--version", [] { return versionText(); },
      "print the version of mbc and of the LLVM it is built on, and exit");
  app.footer("'mbc help COMMAND' or 'mbc COMMAND --help' shows a command's "
             "options.");
  runner::useHelpFormatter(app);
  app.allow_extras();
  app.require_subcommand(0, 1);
  app.option_defaults()->always_capture_default(false);
  defineRun(app, r);
  defineBatch(app, r);
  defineCheck(app, r);
  defineEmitIr(app, r);
  defineCompile(app, r);
  defineBuild(app, r);
  defineLsp(app);
  defineHelp(app, r);
  for (CLI::App* cmd : app.get_subcommands({})) {
    cmd->allow_extras();
    cmd->group("Commands");
  }
  std::vector<std::string> args = cliArguments(argc, argv);
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    std::cout << (chosen.empty() ? app.help() : chosen[0]->help());
    return {};
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what();
    return {};
  } catch (const CLI::ParseError& e) {
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    return {std::nullopt,
            usageError(e.what(), chosen.empty() ? "" : chosen[0]->get_name())};
  }
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  const std::vector<std::string> extra = app.remaining();
  if (!extra.empty()) {
    return {std::nullopt,
            usageError(extra[0].starts_with("-")
                           ? fmt::format("unknown option '{}' (an option of "
                                         "a command follows the command)",
                                         extra[0])
                           : unknownCommandMessage(app, extra[0]),
                       "")};
  }
  if (chosen.empty()) {
    return {std::nullopt, usageError("missing command", "")};
  }
  const CLI::App& cmd = *chosen[0];
  r.o.command = cmd.get_name();
  if (r.o.command == "help") {
    return helpFor(app, r.helpTopic);
  }
  std::string error = unknownArgument(app, cmd);
  if (error.empty()) {
    error = r.error;
  }
  if (error.empty()) {
    error = checkCombinations(r.o);
  }
  if (!error.empty()) {
    return {std::nullopt, usageError(error, r.o.command)};
  }
  r.o.diagnostics.color = colorWanted(r.color);
  return {std::move(r.o), 0};
}

} // namespace mbc::driver
