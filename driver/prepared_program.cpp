// The phases of `mbc run` before the run (see prepared_program.h).
#include "driver/prepared_program.h"

#include "driver/closest_match.h"
#include "driver/ir_pipeline.h"
#include "driver/jit_compiler.h"
#include "interp/interpreter.h"
#include "ir/evaluator.h"
#include <mbc/addresses.h>

#include <fmt/format.h>

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

// "no program 9001 in the input; did you mean 'O9001'?"
std::string missingMainMessage(const Unit& unit, const std::string& wanted) {
  std::vector<std::string> names;
  for (const Program& p : unit.programs) {
    names.push_back(p.name);
  }
  const std::string guess = closestMatch(wanted, names);
  return fmt::format(
      "no program {} in the input{}", wanted,
      guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess));
}

} // namespace

int PreparedProgram::prepare(const Options& o, PhaseTimes& phases) {
  const auto start = std::chrono::steady_clock::now();
  if (!loadUnit(o.files, loadOptions(o), cu_)) {
    return 1;
  }
  phases.emplace_back("front end", millisecondsSince(start));
  if (cu_.unit.programs.empty() && o.run.mainProgram.empty()) {
    std::fprintf(stderr, "mbc: warning: the input has no blocks to run\n");
    return kNothingToRun;
  }
  std::string error;
  const int status = build(o, phases, error);
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

int PreparedProgram::build(const Options& o, PhaseTimes& phases,
                           std::string& error) {
  engine_ = o.engine;
  mainIndex_ = findMain(cu_.unit, o.run.mainProgram);
  if (mainIndex_ < 0) {
    error = o.run.mainProgram.empty()
                ? "the input has no programs"
                : missingMainMessage(cu_.unit, o.run.mainProgram);
    return 2;
  }
  for (const Program& p : cu_.unit.programs) {
    if (isNamedProgramNumber(p.number)) {
      names_.push_back({p.name.c_str(), p.number, nullptr});
    }
  }
  auto start = std::chrono::steady_clock::now();
  std::optional<JitCompiler> jit;
  if (engine_ == EngineKind::Jit) {
    jit.emplace(o, cu_.sources);
    if ((code_ = jit->cached())) {
      phases.emplace_back("cache", millisecondsSince(start));
      return 0;
    }
  }
  if (engine_ != EngineKind::Interp) {
    if (!buildModule(cu_, o, module_) || !optimizeModule(module_, o)) {
      error = "internal error: the IR of the input could not be built";
      return 4;
    }
    phases.emplace_back("IR", millisecondsSince(start));
  }
  start = std::chrono::steady_clock::now();
  if (jit) {
    code_ = jit->compile(module_, error);
    if (!code_) {
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
  if (engine_ == EngineKind::Ir) {
    return ir::evaluate(module_, mainIndex_, ctx);
  }
  Interpreter interp(cu_.unit, cu_.sources, ctx);
  return interp.run(mainIndex_);
}

} // namespace mbc::driver
