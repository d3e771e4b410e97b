// The input compiled for the chosen engine, ready to run its main program
// any number of times, from any number of threads, each with its own
// context: the AST for the interpreter, the IR module for the IR
// evaluator, the JIT's code (generated, or found in the cache). `mbc run` runs
// it once, `mbc batch` once per row of its table.
#pragma once

#include "ir/ir.h"

#include <memory>
#include <string>
#include <vector>

#include "runner/run_session.h"
#include "toolchain/compile_unit.h"
#include "toolchain/native_code.h"
#include "toolchain/request.h"

namespace mbc::toolchain {

class PreparedProgram {
public:
  /// prepare()'s result for an input without blocks (a warning, status 0).
  static constexpr int kNothingToRun = -1;

  /// Compiles `r.files` for `r.engine`, timing the phases. 0 when ready,
  /// kNothingToRun, or an exit status: 1 source errors, 2 no such main
  /// program (--main), 4 internal error. Messages go to stderr.
  int prepare(const Request& r, runner::PhaseTimes& phases);
  /// prepare() in two steps, for inputs given as text too (the Python
  /// package): parse() leaves the diagnostics in `diags`, made for
  /// sources(); false when a file could not be read (`failure` says why).
  bool parse(const std::vector<SourceText>& texts,
             const std::vector<std::string>& files, const LoadOptions& load,
             DiagnosticEngine& diags, std::string& failure);
  /// Then build() finds the main program and makes the engine's code:
  /// 0, or prepare()'s exit status with the reason in `error`.
  int build(const Request& r, runner::PhaseTimes& phases, std::string& error);

  const SourceManager& sources() const { return cu_.sources; }

  const Unit& unit() const { return cu_.unit; }

  /// Runs the main program in a started context. Const: threads share it.
  mbrt_status run(mbrt_ctx* ctx) const;

  const std::string& mainName() const {
    return cu_.unit.programs[mainIndex_].name;
  }

private:
  Engine engine_ = Engine::Jit;
  CompiledUnit cu_;
  ir::Module module_;
  std::unique_ptr<NativeCode> code_;
  std::vector<mbrt_program> names_; // the named programs, for traces
  int mainIndex_ = -1;
};

} // namespace mbc::toolchain
