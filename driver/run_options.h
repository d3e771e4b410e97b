// The options of a run, shared by `mbc run` and the executables `mbc build`
// makes (which take the same ones): outputs, machine, presets, arguments,
// limits, block skip and tracing.
#pragma once

#include "driver/arg_reader.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace mbc::driver {

struct RunOptions {
  std::string mainProgram; // --main O1234 / <NAME>
  std::string toolpathPath;
  std::string gcodePath; // the flattened program
  std::string svgPath;   // the toolpath drawn
  std::string statePath; // nonvolatile variables and offsets, kept
  bool time = false;     // --time: the phases' wall-clock times
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

enum class OptionStatus { NotARunOption, Taken, Error };

/// Takes the reader's current argument when it is a run option.
OptionStatus readRunOption(ArgReader& args, RunOptions& o, std::string& error);

/// The run options' part of a usage text, indented by `indent` spaces.
std::string runOptionsUsage(int indent);

/// Reads a number the way the C locale writes it, whatever the locale.
bool parseNumber(std::string_view text, double& out);

/// A size in bytes: "4096", "64K", "512M", "2G" (1024-based), at least 1.
bool parseSize(std::string_view text, std::uint64_t& out);

} // namespace mbc::driver
