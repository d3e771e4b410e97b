// Command-line options of `mbc run`, `mbc check` and `mbc emit-ir`.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mbc::driver {

struct Options {
  std::string command; // "run", "check" or "emit-ir"
  std::vector<std::string> files;
  std::string mainProgram; // --main O1234 / <NAME>
  std::string engine = "jit";
  int optLevel = 2; // -O0 ... -O3: the LLVM pipeline (jit, compile, build)
  std::string toolpathPath;
  std::string dprntPath;
  std::string varsOutPath;
  std::string machinePath;
  std::vector<std::pair<double, double>> presets; // --set '#N=V'
  std::vector<std::pair<char, double>> args;      // --arg A=1.5
  std::uint64_t maxBlocks = 0;
  unsigned blockSkipMask = 0;
  bool trace = false;
  bool noOpt = false;      // emit-ir, run --engine ir: no passes
  bool verifyEach = false; // verify the IR after every pass
  std::vector<std::string> disabledPasses; // --disable-pass NAME
  std::string language = "nc";             // -x nc|mbir (emit-ir)
};

/// Parses argv; on a usage error returns nullopt after writing the message
/// to `error`.
std::optional<Options> parseOptions(int argc, char** argv, std::string& error);

std::string usageText();

} // namespace mbc::driver
