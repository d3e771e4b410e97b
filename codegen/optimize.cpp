// The LLVM pass pipeline (new pass manager).
#include "codegen/optimize.h"

#include <llvm/Config/llvm-config.h>
#include <llvm/Passes/PassBuilder.h>

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

llvm::CodeGenOpt::Level codeGenLevel(int level) {
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
  llvm::PassBuilder pb(&tm);
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
