// Command-line parsing for the mbc driver: the run options (run_options.h)
// plus those of the compiler.
#include "driver/options.h"

#include "ir/pass_manager.h"

#include <fmt/format.h>

namespace mbc::driver {

namespace {

bool isCommand(const std::string& c) {
  return c == "run" || c == "batch" || c == "check" || c == "emit-ir" ||
         c == "compile" || c == "build";
}

bool setValueOption(Options& o, const std::string& name,
                    const std::string& value, std::string& error) {
  if (name == "--disable-pass") {
    if (!ir::isPassName(value)) {
      error = fmt::format("unknown pass '{}' (passes: {})", value,
                          ir::passNameList());
      return false;
    }
    o.disabledPasses.push_back(value);
  } else if (name == "-x") {
    o.language = value;
  } else if (name == "--engine") {
    o.engine = value;
  } else if (name == "-o") {
    o.outputPath = value;
  } else if (name == "--header") {
    o.headerPath = value;
  } else if (name == "--emit") {
    o.emit = value;
  } else if (name == "--cpu") {
    o.cpu = value;
  } else if (name == "--params") {
    o.paramsPath = value;
  } else if (name == "--out") {
    o.outDir = value;
  } else if (name == "--shard") {
    o.shard = value;
  } else if (name == "-I") {
    o.includeDirs.push_back(value);
  } else if (name == "-j" || name == "--jobs") {
    double jobs = 0;
    if (!parseNumber(value, jobs) || jobs < 1 || jobs > 256 ||
        jobs != static_cast<int>(jobs)) {
      error = fmt::format("{} expects a number of threads from 1 to 256, "
                          "got '{}'",
                          name, value);
      return false;
    }
    o.jobs = static_cast<int>(jobs);
  } else {
    o.tableName = value;
  }
  return true;
}

bool isValueOption(const std::string& name) {
  return name == "--disable-pass" || name == "-x" || name == "--engine" ||
         name == "-o" || name == "--header" || name == "--emit" ||
         name == "--table" || name == "--cpu" || name == "--params" ||
         name == "--out" || name == "--shard" || name == "-I" || name == "-j" ||
         name == "--jobs";
}

bool isCIdentifier(const std::string& s) {
  if (s.empty() || (s[0] >= '0' && s[0] <= '9')) {
    return false;
  }
  for (char c : s) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
              (c >= '0' && c <= '9') || c == '_';
    if (!ok) {
      return false;
    }
  }
  return true;
}

// mbc batch writes every row's outputs under --out, and needs its table.
bool checkBatchOptions(const Options& o, std::string& error) {
  const RunOptions& r = o.run;
  const std::pair<bool, const char*> single[] = {
      {!r.toolpathPath.empty(), "--toolpath"},
      {!r.dprntPath.empty(), "--dprnt"},
      {!r.varsOutPath.empty(), "--vars-out"},
      {!r.gcodePath.empty(), "--gcode"},
      {!r.svgPath.empty(), "--svg"},
      {!r.statePath.empty(), "--state"},
      {r.time, "--time"}};
  const std::pair<bool, const char*> batchOnly[] = {
      {!o.paramsPath.empty(), "--params"},
      {!o.outDir.empty(), "--out"},
      {!o.shard.empty(), "--shard"},
      {o.jobs != 0, "-j"},
      {o.combined, "--combined"}};
  if (o.command != "batch") {
    for (const auto& [given, name] : batchOnly) {
      if (given) {
        error = fmt::format("{} is only available with batch", name);
        return false;
      }
    }
    return true;
  }
  for (const auto& [given, name] : single) {
    if (given) {
      error = fmt::format("{} is an option of mbc run: mbc batch writes "
                          "each row's toolpath, DPRNT, variables and log "
                          "under --out DIR",
                          name);
      return false;
    }
  }
  if (o.paramsPath.empty() || o.outDir.empty()) {
    error = "mbc batch needs --params TABLE.csv and --out DIR";
    return false;
  }
  return true;
}

// The combinations of options that make no sense.
bool checkOptions(const Options& o, std::string& error) {
  bool producesFile = o.command == "compile" || o.command == "build";
  if (o.files.empty()) {
    error = "no input file";
  } else if (o.engine != "interp" && o.engine != "ir" && o.engine != "jit") {
    error = fmt::format("unknown engine '{}' (jit, interp or ir)", o.engine);
  } else if (o.language != "nc" && o.language != "mbir") {
    error = fmt::format("unknown input language '{}' (nc or mbir)", o.language);
  } else if (o.language == "mbir" && o.command != "emit-ir" &&
             o.command != "compile") {
    error = "-x mbir is only available with emit-ir and compile";
  } else if (producesFile && o.outputPath.empty()) {
    error = fmt::format("mbc {} needs -o OUTPUT", o.command);
  } else if (o.emit != "obj" && o.emit != "asm" && o.emit != "llvm" &&
             o.emit != "ir") {
    error = fmt::format("unknown --emit '{}' (ir, llvm, asm or obj)", o.emit);
  } else if (o.noCache && o.command != "run" && o.command != "batch") {
    error = "--no-cache is only available with run and batch";
  } else if (o.shared && o.command != "compile") {
    error = "--shared is only available with compile";
  } else if (o.shared && o.emit != "obj") {
    error =
        fmt::format("--shared writes a shared library, not --emit={}", o.emit);
  } else if (o.shared && o.outputPath == "-") {
    error = "mbc compile --shared needs -o FILE.so";
  } else if (!checkBatchOptions(o, error)) {
    return false;
  } else if (o.command == "check" && o.strict == false) {
    error = "mbc check reports errors as errors; --no-strict is for run, "
            "batch, emit-ir, compile and build";
  } else if (!o.tableName.empty() && !isCIdentifier(o.tableName)) {
    error = fmt::format("--table '{}' is not a C identifier", o.tableName);
  } else {
    return true;
  }
  return false;
}

} // namespace

LoadOptions loadOptions(const Options& o) {
  const bool runs = o.command == "run" || o.command == "batch";
  LoadOptions load;
  load.defaultMachine = o.run.machinePath.empty() && o.command != "compile" &&
                        o.command != "build";
  load.errors = o.strict.value_or(!runs) ? ErrorMode::Refuse : ErrorMode::Alarm;
  load.includeDirs = o.includeDirs;
  return load;
}

std::string usageText() {
  return "usage: mbc run FILE... [--engine jit|interp|ir] [-O0..-O3]\n" +
         runOptionsUsage(8) + "        [--strict] [--no-cache]\n" +
         "        [--no-opt] [--disable-pass NAME]... [--verify-each]\n"
         "       mbc batch FILE... --params TABLE.csv --out DIR [-j N]\n"
         "        [--shard I/N] [--combined] [--engine jit|interp|ir]\n"
         "        [-O0..-O3] [--main O1234] [--set '#N=V']...\n"
         "        [--arg A=1.5]... [--machine PATH] [--max-blocks N]\n"
         "        [--max-output SIZE] [--block-skip[=N]] [--trace] [--strict]\n"
         "        [--no-cache]\n"
         "       mbc check FILE... [--machine PATH]\n"
         "       mbc emit-ir [-x nc|mbir] FILE... [--no-opt] [--trace]\n"
         "        [--disable-pass NAME]... [--verify-each] [--no-strict]\n"
         "       mbc compile -c FILE... -o OUT.o [--header OUT.h]\n"
         "        [--emit=ir|llvm|asm|obj] [--table NAME] [--cpu NAME]\n"
         "        [-O0..-O3] [-g] [--no-strict]\n"
         "       mbc compile --shared FILE... -o LIB.so [--header OUT.h]\n"
         "        [--table NAME] [--cpu NAME] [-O0..-O3] [-g] [-v] "
         "[--no-strict]\n"
         "       mbc build FILE... -o EXE [--cpu NAME] [-O0..-O3] [-g] [-v]\n"
         "        [--no-strict]\n"
         "passes: " +
         ir::passNameList() + "\n";
}

std::optional<Options> parseOptions(int argc, char** argv, std::string& error) {
  Options o;
  if (argc < 2) {
    error = "missing command";
    return std::nullopt;
  }
  o.command = argv[1];
  if (!isCommand(o.command)) {
    error = fmt::format("unknown command '{}'", o.command);
    return std::nullopt;
  }
  ArgReader args(argc, argv, 2);
  while (args.advance()) {
    const std::string& a = args.arg();
    const std::string& name = args.name();
    OptionStatus run = readRunOption(args, o.run, error);
    if (run == OptionStatus::Error) {
      return std::nullopt;
    }
    if (run == OptionStatus::Taken) {
      continue;
    }
    if (a.size() == 3 && a.starts_with("-O") && a[2] >= '0' && a[2] <= '3') {
      o.optLevel = a[2] - '0';
    } else if (a == "-g") {
      o.debugInfo = true;
    } else if (a == "-v") {
      o.verbose = true;
    } else if (a == "--shared") {
      o.shared = true;
    } else if (a == "--no-cache") {
      o.noCache = true;
    } else if (a == "--combined") {
      o.combined = true;
    } else if (a == "--strict" || a == "--no-strict") {
      o.strict = a == "--strict";
    } else if (a == "-c") {
      // compile only: what `mbc compile` always does (as with cc -c)
    } else if (a == "--no-opt") {
      o.noOpt = true;
    } else if (a == "--verify-each") {
      o.verifyEach = true;
    } else if (isValueOption(name)) {
      std::string value;
      if (!args.takeValue(value, error) ||
          !setValueOption(o, name, value, error)) {
        return std::nullopt;
      }
    } else if (a.starts_with("-") && a != "-") {
      error = fmt::format("unknown option '{}'", a);
      return std::nullopt;
    } else {
      o.files.push_back(a);
    }
  }
  if (!checkOptions(o, error)) {
    return std::nullopt;
  }
  return o;
}

} // namespace mbc::driver
