// The phases of `mbc run` before the run (see prepared_program.h).
#include "driver/prepared_program.h"

#include "driver/ir_pipeline.h"
#include "driver/jit_compiler.h"
#include "interp/interpreter.h"
#include "ir/evaluator.h"
#include <mbc/addresses.h>

#include <cstdio>
#include <optional>

namespace mbc::driver {

namespace {

int findMain(const Unit& unit, const std::string& wanted) {
  if (unit.programs.empty()) {
    return -1;
  }
  if (wanted.empty()) {
    return 0;
  }
  for (int i = 0; i < static_cast<int>(unit.programs.size()); ++i) {
    const Program& p = unit.programs[i];
    if (namesProgram(p.name, p.number, wanted)) {
      return i;
    }
  }
  return -1;
}

} // namespace

int PreparedProgram::prepare(const Options& o, PhaseTimes& phases) {
  engine_ = o.engine;
  auto start = std::chrono::steady_clock::now();
  if (!loadUnit(o.files, loadOptions(o), cu_)) {
    return 1;
  }
  phases.emplace_back("front end", millisecondsSince(start));
  if (cu_.unit.programs.empty() && o.run.mainProgram.empty()) {
    std::fprintf(stderr, "mbc: warning: the input has no blocks to run\n");
    return kNothingToRun;
  }
  mainIndex_ = findMain(cu_.unit, o.run.mainProgram);
  if (mainIndex_ < 0) {
    std::fprintf(stderr, "mbc: error: no program %s in the input\n",
                 o.run.mainProgram.c_str());
    return 2;
  }
  for (const Program& p : cu_.unit.programs) {
    if (isNamedProgramNumber(p.number)) {
      names_.push_back({p.name.c_str(), p.number, nullptr});
    }
  }
  start = std::chrono::steady_clock::now();
  std::optional<JitCompiler> jit;
  if (engine_ == "jit") {
    jit.emplace(o, cu_.sources);
    if ((code_ = jit->cached())) {
      phases.emplace_back("cache", millisecondsSince(start));
      return 0;
    }
  }
  if (engine_ != "interp") {
    if (!buildModule(cu_, o, module_) || !optimizeModule(module_, o)) {
      return 4;
    }
    phases.emplace_back("IR", millisecondsSince(start));
  }
  start = std::chrono::steady_clock::now();
  if (jit) {
    std::string error;
    code_ = jit->compile(module_, error);
    if (!code_) {
      std::fprintf(stderr, "mbc: error: %s\n", error.c_str());
      return 4;
    }
    phases.emplace_back("code generation", millisecondsSince(start));
  }
  return 0;
}

mbrt_status PreparedProgram::run(mbrt_ctx* ctx) const {
  const mbrt_program_table names{names_.data(), names_.size()};
  mbrt_name_programs(ctx, &names);
  if (code_) {
    return mbrt_run_body(ctx, &code_->programs()->programs[mainIndex_]);
  }
  if (engine_ == "ir") {
    return ir::evaluate(module_, mainIndex_, ctx);
  }
  Interpreter interp(cu_.unit, cu_.sources, ctx);
  return interp.run(mainIndex_);
}

} // namespace mbc::driver
