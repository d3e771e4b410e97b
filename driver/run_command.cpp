// `mbc run` and its summary line.
#include "driver/run_command.h"

#include "codegen/jit.h"
#include "driver/compile_unit.h"
#include "driver/ir_pipeline.h"
#include "driver/output_files.h"
#include "interp/interpreter.h"
#include "ir/evaluator.h"
#include <mbc/runtime.h>

#include <cstdio>
#include <memory>

namespace mbc::driver {

namespace {

struct CtxDeleter {
  void operator()(mbrt_ctx* c) const { mbrt_destroy(c); }
};

using CtxPtr = std::unique_ptr<mbrt_ctx, CtxDeleter>;

void writeStderr(void*, const char* data, std::size_t size) {
  std::fwrite(data, 1, size, stderr);
}

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

CtxPtr createContext(const Options& o) {
  char err[512] = {0};
  mbrt_ctx* ctx =
      o.machinePath.empty()
          ? mbrt_create(nullptr, err, sizeof err)
          : mbrt_create_from_file(o.machinePath.c_str(), err, sizeof err);
  if (!ctx) {
    std::fprintf(stderr, "mbc: error: machine profile: %s\n", err);
  }
  return CtxPtr(ctx);
}

void printSummary(const mbrt_ctx* ctx, const std::string& program,
                  bool alarmed) {
  mbrt_stats st{};
  mbrt_get_stats(ctx, &st);
  std::fprintf(stderr, "mbc: %s: %llu blocks, %llu moves, %d alarm%s\n",
               program.c_str(), static_cast<unsigned long long>(st.blocks),
               static_cast<unsigned long long>(st.moves), alarmed ? 1 : 0,
               alarmed ? "" : "s");
  if (st.optional_stops) {
    std::fprintf(stderr, "mbc: note: %llu M00/M01 stop(s) passed through\n",
                 static_cast<unsigned long long>(st.optional_stops));
  }
  if (st.main_m99) {
    std::fprintf(stderr, "mbc: note: M99 in the main program ended the run "
                         "(a control would start it again)\n");
  }
}

} // namespace

int runCommand(const Options& o) {
  CompiledUnit cu;
  if (!loadUnit(o.files, false, cu)) {
    return 1;
  }
  if (cu.unit.programs.empty() && o.mainProgram.empty()) {
    std::fprintf(stderr, "mbc: warning: the input has no blocks to run\n");
    return 0;
  }
  int mainIndex = findMain(cu.unit, o.mainProgram);
  if (mainIndex < 0) {
    std::fprintf(stderr, "mbc: error: no program %s in the input\n",
                 o.mainProgram.c_str());
    return 2;
  }
  ir::Module module;
  if (o.engine != "interp" &&
      (!buildModule(cu, o, module) || !optimizeModule(module, o))) {
    return 4;
  }
  std::unique_ptr<codegen::Jit> jit;
  if (o.engine == "jit") {
    std::string error;
    jit = codegen::Jit::compile(module, o.optLevel, error);
    if (!jit) {
      std::fprintf(stderr, "mbc: internal error: %s\n", error.c_str());
      return 4;
    }
  }
  CtxPtr ctx = createContext(o);
  if (!ctx) {
    return 2;
  }
  OutputFile toolpath, dprnt;
  if (!o.toolpathPath.empty()) {
    if (!toolpath.open(o.toolpathPath)) {
      std::fprintf(stderr, "mbc: error: cannot write '%s'\n",
                   o.toolpathPath.c_str());
      return 2;
    }
    mbrt_set_motion_sink(ctx.get(), &OutputFile::writeMotion, &toolpath);
  }
  if (o.dprntPath.empty()) {
    dprnt.useStdout();
  } else if (!dprnt.open(o.dprntPath)) {
    std::fprintf(stderr, "mbc: error: cannot write '%s'\n",
                 o.dprntPath.c_str());
    return 2;
  }
  mbrt_set_print_sink(ctx.get(), &OutputFile::writeText, &dprnt);
  mbrt_set_message_sink(ctx.get(), &writeStderr, nullptr);
  if (o.trace) {
    mbrt_set_trace_sink(ctx.get(), &writeStderr, nullptr);
  }
  if (o.maxBlocks) {
    mbrt_set_max_blocks(ctx.get(), o.maxBlocks);
  }
  const Program& main = cu.unit.programs[mainIndex];
  mbrt_start(ctx.get(), main.name.c_str());
  mbrt_status st = 0;
  for (auto [number, value] : o.presets) {
    if ((st = mbrt_write_var(ctx.get(), number, value, nullptr))) {
      break;
    }
  }
  if (!st && !o.args.empty()) {
    std::vector<mbrt_word> words;
    for (auto [letter, value] : o.args) {
      words.push_back({letter, MBRT_WORD_VALUE, value});
    }
    st = mbrt_set_main_args(ctx.get(), words.data(), words.size());
  }
  if (!st) {
    mbrt_set_block_skip(ctx.get(), o.blockSkipMask);
    MathParams math;
    math.nat = (static_cast<long>(mbrt_parameter(ctx.get(), 6004)) & 1) != 0;
    if (jit) {
      st = mbrt_run_body(ctx.get(), &jit->programs()->programs[mainIndex]);
    } else if (o.engine == "ir") {
      ir::EvalOptions eo{math};
      st = ir::evaluate(module, mainIndex, ctx.get(), eo);
    } else {
      Interpreter interp(cu.unit, cu.sources, ctx.get(), InterpOptions{math});
      st = interp.run(mainIndex);
    }
  }
  if (st) {
    char report[4096];
    mbrt_alarm_report(ctx.get(), report, sizeof report);
    std::fflush(stdout);
    std::fputs(report, stderr);
  }
  if (!o.varsOutPath.empty() && !writeVariables(ctx.get(), o.varsOutPath)) {
    std::fprintf(stderr, "mbc: error: cannot write '%s'\n",
                 o.varsOutPath.c_str());
  }
  printSummary(ctx.get(), main.name, st != 0);
  return st ? 3 : 0;
}

} // namespace mbc::driver
