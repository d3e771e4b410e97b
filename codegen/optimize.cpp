// The LLVM pass pipeline (new pass manager).
#include "codegen/optimize.h"

#include <llvm/Config/llvm-config.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Passes/StandardInstrumentations.h>

namespace mbc::codegen {

namespace {

llvm::OptimizationLevel passLevel(int level) {
  switch (level) {
    case 1:
      return llvm::OptimizationLevel::O1;
    case 2:
      return llvm::OptimizationLevel::O2;
    default:
      // LLVM 14's O3 pipeline adds ArgumentPromotion, which crashes on
      // opaque pointers; -O3 keeps the O2 passes and the aggressive code
      // generator there.
#if LLVM_VERSION_MAJOR < 15
      return llvm::OptimizationLevel::O2;
#else
      return llvm::OptimizationLevel::O3;
#endif
  }
}

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

void optimize(llvm::Module& module, llvm::TargetMachine& tm, int level) {
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
  llvm::ModulePassManager mpm =
      level <= 0 ? pb.buildO0DefaultPipeline(llvm::OptimizationLevel::O0)
                 : pb.buildPerModuleDefaultPipeline(passLevel(level));
  mpm.run(module, mam);
}

} // namespace mbc::codegen
