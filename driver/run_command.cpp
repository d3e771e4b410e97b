// `mbc run`: the input compiled for the chosen engine, then one run session.
#include "driver/run_command.h"

#include "codegen/jit.h"
#include "driver/compile_unit.h"
#include "driver/ir_pipeline.h"
#include "driver/run_session.h"
#include "interp/interpreter.h"
#include "ir/evaluator.h"
#include <mbc/runtime.h>

#include <cstdio>
#include <memory>

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

int runCommand(const Options& o) {
  PhaseTimes phases;
  auto start = std::chrono::steady_clock::now();
  CompiledUnit cu;
  if (!loadUnit(o.files, false, cu)) {
    return 1;
  }
  phases.emplace_back("front end", millisecondsSince(start));
  if (cu.unit.programs.empty() && o.run.mainProgram.empty()) {
    std::fprintf(stderr, "mbc: warning: the input has no blocks to run\n");
    return 0;
  }
  int mainIndex = findMain(cu.unit, o.run.mainProgram);
  if (mainIndex < 0) {
    std::fprintf(stderr, "mbc: error: no program %s in the input\n",
                 o.run.mainProgram.c_str());
    return 2;
  }
  ir::Module module;
  start = std::chrono::steady_clock::now();
  if (o.engine != "interp") {
    if (!buildModule(cu, o, module) || !optimizeModule(module, o)) {
      return 4;
    }
    phases.emplace_back("IR", millisecondsSince(start));
  }
  std::unique_ptr<codegen::Jit> jit;
  start = std::chrono::steady_clock::now();
  if (o.engine == "jit") {
    std::string error;
    codegen::JitOptions jo;
    jo.optLevel = o.optLevel;
    jo.debugInfo = o.debugInfo;
    jit = codegen::Jit::compile(module, jo, error);
    if (!jit) {
      std::fprintf(stderr, "mbc: internal error: %s\n", error.c_str());
      return 4;
    }
    phases.emplace_back("code generation", millisecondsSince(start));
  }
  return runSession(
      o.run, cu.unit.programs[mainIndex].name,
      [&](mbrt_ctx* ctx) -> mbrt_status {
        if (jit) {
          return mbrt_run_body(ctx, &jit->programs()->programs[mainIndex]);
        }
        if (o.engine == "ir") {
          return ir::evaluate(module, mainIndex, ctx);
        }
        Interpreter interp(cu.unit, cu.sources, ctx);
        return interp.run(mainIndex);
      },
      phases);
}

} // namespace mbc::driver
