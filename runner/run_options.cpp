// Run options. Numbers are read with from_chars so that the locale never
// changes their meaning.
#include "runner/run_options.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>

namespace mbc::runner {

bool parseNumber(std::string_view text, double& out) {
  if (!text.empty() && text[0] == '+') {
    text.remove_prefix(1);
  }
  auto res = std::from_chars(text.data(), text.data() + text.size(), out);
  // inf and nan are no values a variable can hold (spec §2.4).
  return res.ec == std::errc() && res.ptr == text.data() + text.size() &&
         std::isfinite(out);
}

bool parseSize(std::string_view text, std::uint64_t& out) {
  double unit = 1;
  if (!text.empty()) {
    const char suffix = text.back();
    const std::string_view units = "KMGT";
    const auto pos = units.find(static_cast<char>(suffix & ~0x20));
    if (pos != std::string_view::npos) {
      unit = static_cast<double>(std::uint64_t{1} << (10 * (pos + 1)));
      text.remove_suffix(1);
    }
  }
  double n = 0;
  if (!parseNumber(text, n) || n * unit < 1 || n * unit > 0x1p63) {
    return false;
  }
  out = static_cast<std::uint64_t>(n * unit);
  return true;
}

namespace {

// "#N=V" (the '#' is optional)
bool parsePreset(std::string_view text, std::pair<double, double>& out) {
  if (!text.empty() && text[0] == '#') {
    text.remove_prefix(1);
  }
  auto eq = text.find('=');
  return eq != std::string_view::npos &&
         parseNumber(text.substr(0, eq), out.first) &&
         parseNumber(text.substr(eq + 1), out.second);
}

// "A=1.5"
bool parseArg(std::string_view text, std::pair<char, double>& out) {
  if (text.size() < 3 || text[1] != '=') {
    return false;
  }
  char c = text[0];
  if (c >= 'a' && c <= 'z') {
    c = static_cast<char>(c - 'a' + 'A');
  }
  out.first = c;
  return c >= 'A' && c <= 'Z' && parseNumber(text.substr(2), out.second);
}

} // namespace

std::string runOptionsProblem(const RunOptions& o) {
  if (o.svgViewGiven && o.svgPath.empty()) {
    return "--view chooses the view of --svg, which is not given";
  }
  if (o.writerThreadGiven && o.toolpathPath.empty() && o.svgPath.empty() &&
      o.htmlPath.empty()) {
    return "--writer-thread chooses how --toolpath, --svg and --html are "
           "made, and none is given";
  }
  if (o.writerThread == WriterThread::On && o.toolpathPath == "-") {
    return "--writer-thread on needs --toolpath FILE: the toolpath on "
           "standard output is written in order with DPRNT";
  }
  return "";
}

CLI::Option* addValueOption(CLI::App& app, const std::string& names,
                            const std::string& valueName,
                            const std::string& help, std::string& error,
                            ValueSetter set) {
  return app.add_option(names, help)
      ->type_name(valueName)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->each([&error, set = std::move(set)](const std::string& value) {
        std::string problem = set(value);
        if (error.empty()) {
          error = std::move(problem);
        }
      });
}

void addRunOptions(CLI::App& app, RunOptions& o, std::string& error,
                   RunOutputs outputs) {
  const auto path = [&](const char* name, std::string& field,
                        const char* help) {
    addValueOption(app, name, "PATH", help, error,
                   [&field](const std::string& v) {
                     field = v;
                     return std::string();
                   })
        ->group("Outputs");
  };
  if (outputs == RunOutputs::Single) {
    path("--toolpath", o.toolpathPath,
         "write the toolpath, one JSON record a motion ('-': standard output)");
    path("--dprnt", o.dprntPath,
         "write DPRNT/BPRNT output here (default: standard output)");
    path("--vars-out", o.varsOutPath,
         "write the variables set at the end as JSON");
    path("--gcode", o.gcodePath,
         "write the flattened program: the motion blocks as plain G-code");
    path("--svg", o.svgPath,
         "draw the toolpath as an SVG picture: holes, origin, legend, "
         "feeds coloured by depth");
    path("--html", o.htmlPath,
         "write the toolpath as one HTML page to open in a browser: a 3D "
         "view to rotate, pan and zoom, the cut move by move, the source "
         "line of a move");
    addValueOption(app, "--view", "xy|xz|yz|zx|iso",
                   "the view --svg draws (default: xy, from above; zx, Z "
                   "right and X up, on a lathe)",
                   error,
                   [&o](const std::string& v) -> std::string {
                     o.svgViewGiven = true;
                     return parseSvgView(v, o.svgView)
                                ? ""
                                : fmt::format("unknown view '{}' (xy, xz, yz, "
                                              "zx or iso)",
                                              v);
                   })
        ->group("Outputs");
    addValueOption(app, "--writer-thread", "auto|on|off",
                   "make the --toolpath file, the --svg drawing and the "
                   "--html page on a thread of their own while the run goes "
                   "on (default: auto, when the process may run on a "
                   "second core)",
                   error,
                   [&o](const std::string& v) -> std::string {
                     o.writerThreadGiven = true;
                     if (v == "auto") {
                       o.writerThread = WriterThread::Auto;
                     } else if (v == "on") {
                       o.writerThread = WriterThread::On;
                     } else if (v == "off") {
                       o.writerThread = WriterThread::Off;
                     } else {
                       return fmt::format(
                           "unknown --writer-thread '{}' (auto, on or off)", v);
                     }
                     return std::string();
                   })
        ->group("Outputs");
    path("--state", o.statePath,
         "keep nonvolatile variables and offsets in this file from run to "
         "run");
    app.add_flag_callback(
           "--time", [&o] { o.time = true; },
           std::string("print the wall-clock time of each phase"))
        ->group("Outputs");
  }
  const auto run = [&](const char* name, const char* valueName,
                       const char* help, ValueSetter set) {
    addValueOption(app, name, valueName, help, error, std::move(set))
        ->group("Run");
  };
  run("--main", "O1234|<NAME>",
      "the program to run (default: the first one in the input)",
      [&o](const std::string& v) {
        o.mainProgram = v;
        return std::string();
      });
  run("--machine", "PATH", "the machine profile (JSON)",
      [&o](const std::string& v) {
        o.machinePath = v;
        return std::string();
      });
  run("--set", "'#N=V'", "set variable #N to V before the run (repeatable)",
      [&o](const std::string& v) {
        std::pair<double, double> p;
        if (!parsePreset(v, p)) {
          return fmt::format("--set expects '#N=V', got '{}'", v);
        }
        o.presets.push_back(p);
        return std::string();
      });
  run("--arg", "A=1.5",
      "a G65 argument of the main program: its local variable (repeatable)",
      [&o](const std::string& v) {
        std::pair<char, double> p;
        if (!parseArg(v, p)) {
          return fmt::format("--arg expects LETTER=VALUE, got '{}'", v);
        }
        o.args.push_back(p);
        return std::string();
      });
  run("--max-blocks", "N", "stop with an alarm after N blocks",
      [&o](const std::string& v) {
        double n = 0;
        if (!parseNumber(v, n) || n < 1) {
          return std::string("--max-blocks expects a positive number");
        }
        o.maxBlocks = static_cast<std::uint64_t>(n);
        return std::string();
      });
  run("--max-output", "SIZE",
      "stop with an alarm after SIZE bytes of output (4096, 64K, 512M, 2G)",
      [&o](const std::string& v) {
        if (!parseSize(v, o.maxOutput)) {
          return fmt::format("--max-output expects a size in bytes such as "
                             "4096, 64K, 512M or 2G, got '{}'",
                             v);
        }
        return std::string();
      });
  // A flag with an optional value written --block-skip=N: block skip
  // switch 1 unless a number is given.
  const std::string blockSkipHelp =
      "turn on block skip switch N (1 to 9; default 1)";
  app.add_flag("--block-skip{1}", blockSkipHelp)
      ->type_name("[=N]")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->each([&o, &error](const std::string& v) {
        double n = 0;
        if (!parseNumber(v, n) || n < 1 || n > 9 || n != static_cast<int>(n)) {
          if (error.empty()) {
            error = "--block-skip takes a switch number 1 to 9";
          }
          return;
        }
        o.blockSkipMask |= 1U << static_cast<unsigned>(n);
      })
      ->group("Run");
  app.add_flag_callback(
         "--trace", [&o] { o.trace = true; },
         std::string("print each block as it runs, with its values"))
      ->group("Run");
}

} // namespace mbc::runner
