// The phases of `mbc run` before the run (see prepared_program.h).
#include "driver/prepared_program.h"

#include "driver/ir_pipeline.h"
#include "interp/interpreter.h"
#include "ir/evaluator.h"

#include <cstdio>
#include <cstdlib>

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
    bool numberMatch = (wanted[0] == 'O' || wanted[0] == 'o') &&
                       p.number >= 0 &&
                       std::atoi(wanted.c_str() + 1) == p.number;
    if (numberMatch || p.name == wanted) {
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
  start = std::chrono::steady_clock::now();
  if (engine_ != "interp") {
    if (!buildModule(cu_, o, module_) || !optimizeModule(module_, o)) {
      return 4;
    }
    phases.emplace_back("IR", millisecondsSince(start));
  }
  start = std::chrono::steady_clock::now();
  if (engine_ == "jit") {
    std::string error;
    codegen::JitOptions jo;
    jo.optLevel = o.optLevel;
    jo.debugInfo = o.debugInfo;
    jit_ = codegen::Jit::compile(module_, jo, error);
    if (!jit_) {
      std::fprintf(stderr, "mbc: internal error: %s\n", error.c_str());
      return 4;
    }
    phases.emplace_back("code generation", millisecondsSince(start));
  }
  return 0;
}

mbrt_status PreparedProgram::run(mbrt_ctx* ctx) const {
  if (jit_) {
    return mbrt_run_body(ctx, &jit_->programs()->programs[mainIndex_]);
  }
  if (engine_ == "ir") {
    return ir::evaluate(module_, mainIndex_, ctx);
  }
  Interpreter interp(cu_.unit, cu_.sources, ctx);
  return interp.run(mainIndex_);
}

} // namespace mbc::driver
