// The standard LLVM optimisation pipeline at -O0 ... -O3.
#pragma once

#include <llvm/IR/Module.h>
#include <llvm/Target/TargetMachine.h>

namespace mbc::codegen {

/// Runs the default per-module pipeline for `level` (0..3) tuned for `tm`.
void optimize(llvm::Module& module, llvm::TargetMachine& tm, int level);

/// The code generator's optimisation level for `level` (0..3).
llvm::CodeGenOpt::Level codeGenLevel(int level);

} // namespace mbc::codegen
