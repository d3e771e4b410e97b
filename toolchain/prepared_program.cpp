// The phases of `mbc run` before the run (see prepared_program.h).
#include "toolchain/prepared_program.h"

#include "interp/interpreter.h"
#include "ir/evaluator.h"
#include <mbc/addresses.h>

#include <fmt/format.h>

#include <cstdio>
#include <optional>

#include "toolchain/ir_pipeline.h"
#include "toolchain/jit_compiler.h"
#include "toolchain/main_program.h"

namespace mbc::toolchain {

int PreparedProgram::prepare(const Request& r, runner::PhaseTimes& phases) {
  const auto start = std::chrono::steady_clock::now();
  if (!loadUnit(r.files, r.load, cu_)) {
    return 1;
  }
  phases.emplace_back("front end", runner::millisecondsSince(start));
  if (cu_.unit.programs.empty() && r.mainProgram.empty()) {
    std::fprintf(stderr, "mbc: warning: the input has no blocks to run\n");
    return kNothingToRun;
  }
  std::string error;
  const int status = build(r, phases, error);
  if (status != 0) {
    std::fprintf(stderr, "mbc: error: %s\n", error.c_str());
  }
  return status;
}

bool PreparedProgram::parse(const std::vector<SourceText>& texts,
                            const std::vector<std::string>& files,
                            const LoadOptions& load, DiagnosticEngine& diags,
                            std::string& failure) {
  return parseInputs(texts, files, load, cu_, diags, failure);
}

int PreparedProgram::build(const Request& r, runner::PhaseTimes& phases,
                           std::string& error) {
  engine_ = r.engine;
  mainIndex_ = findMain(cu_.unit, r.mainProgram);
  if (mainIndex_ < 0) {
    error = r.mainProgram.empty() ? "the input has no programs"
                                  : missingMainMessage(cu_.unit, r.mainProgram);
    return 2;
  }
  for (const Program& p : cu_.unit.programs) {
    if (isNamedProgramNumber(p.number)) {
      names_.push_back({p.name.c_str(), p.number, nullptr});
    }
  }
  auto start = std::chrono::steady_clock::now();
  std::optional<JitCompiler> jit;
  if (engine_ == Engine::Jit) {
    jit.emplace(r, cu_.sources);
    if ((code_ = jit->cached())) {
      phases.emplace_back("cache", runner::millisecondsSince(start));
      return 0;
    }
  }
  if (engine_ != Engine::Interp) {
    if (!buildModule(cu_, r.trace, module_) ||
        !optimizeModule(module_, r.passes)) {
      error = "internal error: the IR of the input could not be built";
      return 4;
    }
    phases.emplace_back("IR", runner::millisecondsSince(start));
  }
  start = std::chrono::steady_clock::now();
  if (jit) {
    code_ = jit->compile(module_, error);
    if (!code_) {
      return 4;
    }
    phases.emplace_back("code generation", runner::millisecondsSince(start));
  }
  return 0;
}

mbrt_status PreparedProgram::run(mbrt_ctx* ctx) const {
  const mbrt_program_table names{names_.data(), names_.size()};
  mbrt_name_programs(ctx, &names);
  if (code_) {
    return mbrt_run_body(ctx, &code_->programs()->programs[mainIndex_]);
  }
  if (engine_ == Engine::Ir) {
    return ir::evaluate(module_, mainIndex_, ctx);
  }
  Interpreter interp(cu_.unit, cu_.sources, ctx);
  return interp.run(mainIndex_);
}

} // namespace mbc::toolchain
