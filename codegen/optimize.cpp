// The LLVM pass pipeline (new pass manager).
#include "codegen/optimize.h"

#include <llvm/Config/llvm-config.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Passes/StandardInstrumentations.h>

namespace mbc::codegen {

namespace {

// LLVM 14's O3 pipeline adds ArgumentPromotion, which crashes on opaque
// pointers; -O3 keeps the O2 passes and the aggressive code generator there.
llvm::OptimizationLevel standardLevel() {
#if LLVM_VERSION_MAJOR < 15
  return llvm::OptimizationLevel::O2;
#else
  return llvm::OptimizationLevel::O3;
#endif
}

// -O1 and -O2: only the function passes that pay on what mbc emits, since
// its own IR passes did the rest (promotion, folding, CSE, load
// elimination): the slots of runtime results into registers, the loads and
// stores of the block state that calls do not separate, the vacancy selects
// and zero adds that fold, the block counter of a loop without calls in a
// register. The bodies call each other only through the program table, so
// LLVM's standard pipelines spent their time on inlining and
// interprocedural passes that found nothing. -O1 takes 2.0 s instead of
// 5.4 s on a 10 000-line program; -O2 adds loop rotation and GVN and takes
// a quarter of the standard O2 pipeline's time on it (1.6 s against 6.9 s
// in opt), and both give the instruction counts of the standard O2 on bench/
// (within 0.1%). -O3 is LLVM's standard pipeline.
constexpr const char* kO1Pipeline =
    "function(sroa,early-cse<memssa>,instcombine,simplifycfg,"
    "loop-mssa(licm),instcombine,simplifycfg)";
constexpr const char* kO2Pipeline =
    "function(sroa,early-cse<memssa>,instcombine,simplifycfg,"
    "loop-simplify,lcssa,loop-rotate,loop-mssa(licm),gvn,instcombine,"
    "simplifycfg)";

} // namespace

llvm::CodeGenOpt::Level codeGenLevel(int level, const llvm::Module& module) {
  for (const llvm::Function& f : module) {
    if (f.hasFnAttribute(llvm::Attribute::OptimizeNone)) {
      return llvm::CodeGenOpt::None;
    }
  }
  switch (level) {
    case 0:
      return llvm::CodeGenOpt::None;
    case 1:
      return llvm::CodeGenOpt::Less;
    case 2:
      return llvm::CodeGenOpt::Default;
    default:
      return llvm::CodeGenOpt::Aggressive;
  }
}

void optimize(llvm::Module& module, llvm::TargetMachine& tm, int level,
              int sizeLevel) {
  for (llvm::Function& f : module) {
    if (sizeLevel > 0 && !f.isDeclaration() &&
        !f.hasFnAttribute(llvm::Attribute::OptimizeNone)) {
      f.addFnAttr(llvm::Attribute::OptimizeForSize);
      if (sizeLevel > 1) {
        f.addFnAttr(llvm::Attribute::MinSize);
      }
    }
  }
  // LLVM's -O0 pipeline only inlines always-inline functions and lowers
  // coroutines, of which mbc emits none; it built a call graph of the
  // whole module for that.
  if (level <= 0) {
    return;
  }
  llvm::LoopAnalysisManager lam;
  llvm::FunctionAnalysisManager fam;
  llvm::CGSCCAnalysisManager cgam;
  llvm::ModuleAnalysisManager mam;
  // The standard instrumentation is what makes passes skip functions
  // marked optnone (emit_module.cpp marks the huge ones).
  llvm::PassInstrumentationCallbacks pic;
#if LLVM_VERSION_MAJOR >= 17
  llvm::StandardInstrumentations si(module.getContext(), false);
  si.registerCallbacks(pic, &mam);
#else
  llvm::StandardInstrumentations si(false);
  si.registerCallbacks(pic, &fam);
#endif
  llvm::PassBuilder pb(&tm, llvm::PipelineTuningOptions(), {}, &pic);
  pb.registerModuleAnalyses(mam);
  pb.registerCGSCCAnalyses(cgam);
  pb.registerFunctionAnalyses(fam);
  pb.registerLoopAnalyses(lam);
  pb.crossRegisterProxies(lam, fam, cgam, mam);
  llvm::ModulePassManager mpm;
  if (level <= 2) {
    if (llvm::Error e =
            pb.parsePassPipeline(mpm, level == 1 ? kO1Pipeline : kO2Pipeline)) {
      llvm::report_fatal_error(std::move(e));
    }
  } else {
    mpm = pb.buildPerModuleDefaultPipeline(standardLevel());
  }
  mpm.run(module, mam);
}

} // namespace mbc::codegen
