// The LLVM optimisation pipeline at -O0 ... -O3: none at -O0, a short list
// of function passes at -O1, LLVM's standard pipelines above.
#pragma once

#include <llvm/IR/Module.h>
#include <llvm/Target/TargetMachine.h>

namespace mbc::codegen {

/// Runs the pipeline for `level` (0..3) tuned for `tm`, after marking the
/// functions optsize (sizeLevel 1) or optsize and minsize (2).
void optimize(llvm::Module& module, llvm::TargetMachine& tm, int level,
              int sizeLevel);

/// The code generator's optimisation level for `level` (0..3), or None
/// when the module has a body too big to optimise (see emit_module.cpp):
/// the register allocator of the higher levels grows faster than linearly
/// on it.
llvm::CodeGenOpt::Level codeGenLevel(int level, const llvm::Module& module);

} // namespace mbc::codegen
