// The options of a run, shared by `mbc run`, `mbc batch` and the executables
// `mbc build` makes (which take the same ones): outputs, machine, presets,
// arguments, limits, block skip and tracing.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "runner/svg_writer.h"

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace mbc::runner {

/// Whether `--toolpath FILE` is written on a thread of its own.
enum class WriterThread {
  Auto, // where a second core is free
  On,
  Off
};

struct RunOptions {
  std::string mainProgram; // --main O1234 / <NAME>
  std::string toolpathPath;
  std::string gcodePath; // the flattened program
  std::string svgPath;   // the toolpath drawn
  SvgView svgView = SvgView::Auto;
  bool svgViewGiven = false; // --view: an error without --svg
  std::string htmlPath;      // the toolpath as an interactive 3D page
  std::string statePath;     // nonvolatile variables and offsets, kept
  bool time = false;         // --time: the phases' wall-clock times
  WriterThread writerThread = WriterThread::Auto;
  bool writerThreadGiven = false; // an error without --toolpath FILE
  std::string dprntPath;
  std::string varsOutPath;
  std::string machinePath;
  std::vector<std::pair<double, double>> presets; // --set '#N=V'
  std::vector<std::pair<char, double>> args;      // --arg A=1.5
  std::uint64_t maxBlocks = 0;
  std::uint64_t maxOutput = 0; // bytes; 0: the runtime's default
  unsigned blockSkipMask = 0;
  bool trace = false;
};

/// Checks and stores one value of an option; returns what is wrong with it,
/// or "" when it is good.
using ValueSetter = std::function<std::string(const std::string& value)>;

/// Adds an option that takes a value (`--name V`, `--name=V`, `-nV`) to
/// `app`. Each value given goes through `set` in turn (a repeated option
/// adds, or the last one wins); the first bad value's message goes to
/// `error`, for the caller to report once the line is read.
CLI::Option* addValueOption(CLI::App& app, const std::string& names,
                            const std::string& valueName,
                            const std::string& help, std::string& error,
                            ValueSetter set);

/// Which run options a command takes.
enum class RunOutputs {
  Single, // a run's output files (mbc run, the executables)
  None    // mbc batch: each row's outputs go under --out DIR
};

/// Adds the run options to `app`, in the help groups "Run" and "Outputs".
void addRunOptions(CLI::App& app, RunOptions& o, std::string& error,
                   RunOutputs outputs);

/// What is wrong with the run options as a whole ("" when nothing): an
/// option that would do nothing without another.
std::string runOptionsProblem(const RunOptions& o);

/// Reads a number the way the C locale writes it, whatever the locale.
bool parseNumber(std::string_view text, double& out);

/// A size in bytes: "4096", "64K", "512M", "2G" (1024-based), at least 1.
bool parseSize(std::string_view text, std::uint64_t& out);

} // namespace mbc::runner
