// Command-line options of `mbc run`, `mbc batch`, `mbc check`, `mbc
// emit-ir`, `mbc compile` and `mbc build`.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runner/run_options.h"
#include "toolchain/argument_ranges.h"
#include "toolchain/compile_unit.h"
#include "toolchain/engine.h"
#include "toolchain/request.h"

namespace mbc::driver {

struct Options {
  std::string command; // run, check, emit-ir, compile, build
  std::vector<std::string> files;
  runner::RunOptions run;
  toolchain::Engine engine = toolchain::Engine::Jit;
  int optLevel = 2;        // -O0 ... -O3: the LLVM pipeline
  int sizeLevel = 0;       // -Os 1, -Oz 2: smaller code
  bool debugInfo = false;  // -g
  bool noCache = false;    // --no-cache (run, batch): the JIT skips the cache
  bool noOpt = false;      // no IR passes
  bool verifyEach = false; // verify the IR after every pass
  std::vector<std::string> disabledPasses; // --disable-pass NAME
  std::string language = "nc";             // -x nc|mbir (emit-ir)
  std::string outputPath;                  // -o (compile, build)
  std::string headerPath;                  // --header (compile)
  std::string emit = "obj";                // --emit=ir|llvm|asm|obj
  std::string tableName;                   // --table (compile)
  std::string cpu;      // --cpu (compile, build): "" generic, "native", a name
  bool shared = false;  // --shared (compile): a shared library
  bool verbose = false; // -v (compile --shared, build): the link command
  std::string paramsPath; // --params TABLE.csv (batch)
  std::string outDir;     // --out DIR (batch)
  std::string shard;      // --shard I/N (batch)
  int jobs = 0;           // -j N (batch): threads; 0 = one per core
  bool combined = false;  // --combined (batch): one JSONL file
  bool resume = false;    // --resume (batch): keep the rows done in --out
  // --column NAME=TARGET (batch): a table column read as another
  std::vector<std::pair<std::string, std::string>> columnMap;
  // --strict / --no-strict: whether errors in the input refuse it, or make
  // their blocks alarm when they run (loadOptions()).
  std::optional<bool> strict;
  std::vector<std::string> includeDirs; // -I DIR: where called programs are
  toolchain::DiagnosticOutput
      diagnostics; // --diagnostics-format, --color, -w, -Werror
  // check --arg X=0..20 and --prove: the range analysis of alarms
  std::vector<toolchain::ArgumentRange> argRanges;
  bool prove = false;
};

/// How the commands read their input (compile_unit.h). Errors in the input:
/// run and batch run it and alarm where the control would; check, emit-ir,
/// compile and build refuse it (a build should fail loudly); --strict and
/// --no-strict choose.
toolchain::LoadOptions loadOptions(const Options& o);

/// What the toolchain compiles for a command: the files, how they are
/// read, the engine, the main program and the options that change the
/// code.
toolchain::Request toolchainRequest(const Options& o);

} // namespace mbc::driver
