// What the toolchain compiles and how: the typed request that the driver
// makes from its command line (driver/options.h) and the Python package
// from its arguments.
#pragma once

#include <string>
#include <vector>

#include "toolchain/compile_unit.h"
#include "toolchain/engine.h"

namespace mbc::toolchain {

/// The IR passes (ir/passes/passes.def).
struct IrPasses {
  bool run = true;                   // --no-opt: none
  bool verifyEach = false;           // verify the IR after every pass
  std::vector<std::string> disabled; // --disable-pass NAME
};

/// How LLVM generates code.
struct CodeLevel {
  int optLevel = 2;       // -O0 ... -O3
  int sizeLevel = 0;      // -Os 1, -Oz 2
  bool debugInfo = false; // -g
};

struct Request {
  std::vector<std::string> files;
  LoadOptions load; // how the input is read and checked
  Engine engine = Engine::Jit;
  std::string mainProgram; // --main: "" for the input's first program
  bool trace = false;      // --trace: a trace instruction per statement
  IrPasses passes;
  CodeLevel code;
  bool useCache = true; // the JIT looks in the compiled-code cache first
};

} // namespace mbc::toolchain
