// difftest_engines FILE MAX_BLOCKS DIR [RUN OPTION]...: runs FILE as `mbc
// run FILE --engine E [-O] --trace --max-blocks N --toolpath ... --dprnt ...
// --vars-out ... [RUN OPTION]...` would, under the interpreter, the IR
// evaluator and the JIT at -O0, -O1 and -O2, all in this one process (through
// runCommand, as mbc run does), and writes what each run wrote to DIR/<k>/
// (status, stderr, toolpath.jsonl, dprnt, vars.json; k in that order).
// tools/difftest.py --engines uses it for long runs: one process start
// instead of five per program.
#include "driver/run_command.h"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <utility>

#include "runner/run_options.h"
#include "toolchain/engine.h"

using namespace mbc::driver;
using namespace mbc::runner;

namespace {

struct Config {
  mbc::toolchain::Engine engine;
  int optLevel;
};

constexpr Config kConfigs[] = {{mbc::toolchain::Engine::Interp, 2},
                               {mbc::toolchain::Engine::Ir, 2},
                               {mbc::toolchain::Engine::Jit, 0},
                               {mbc::toolchain::Engine::Jit, 1},
                               {mbc::toolchain::Engine::Jit, 2}};

// One run as `mbc run` makes it, standard error going to `dir/stderr`.
int runConfig(const Config& c, const std::string& file, RunOptions run,
              const std::string& dir) {
  Options o;
  o.command = "run";
  o.files = {file};
  o.engine = c.engine;
  o.optLevel = c.optLevel;
  o.run = std::move(run);
  o.run.trace = true;
  o.run.toolpathPath = dir + "/toolpath.jsonl";
  o.run.dprntPath = dir + "/dprnt";
  o.run.varsOutPath = dir + "/vars.json";
  return runCommand(o);
}

} // namespace

int main(int argc, char** argv) {
  RunOptions run;
  double limit = 0;
  if (argc < 4 || !parseNumber(argv[2], limit)) {
    std::fprintf(
        stderr,
        "usage: difftest_engines FILE MAX_BLOCKS DIR [RUN OPTION]...\n");
    return 2;
  }
  run.maxBlocks = static_cast<std::uint64_t>(limit);
  CLI::App app("difftest_engines");
  std::string error;
  addRunOptions(app, run, error, RunOutputs::None);
  try {
    app.parse(argc - 3, argv + 3);
  } catch (const CLI::ParseError& e) {
    error = e.what();
  }
  if (!error.empty()) {
    std::fprintf(stderr, "difftest_engines: %s\n", error.c_str());
    return 2;
  }
  const int savedStderr = dup(STDERR_FILENO);
  for (std::size_t k = 0; k < std::size(kConfigs); ++k) {
    const std::string dir = std::string(argv[3]) + "/" + std::to_string(k);
    std::filesystem::create_directories(dir);
    std::fflush(stderr);
    const int err =
        open((dir + "/stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(err, STDERR_FILENO);
    close(err);
    const int status = runConfig(kConfigs[k], argv[1], run, dir);
    std::fflush(stderr);
    dup2(savedStderr, STDERR_FILENO);
    std::ofstream(dir + "/status") << status;
  }
  return 0;
}
