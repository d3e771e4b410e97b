// IR -> LLVM IR: one module per mbc module. Every program becomes an
// internal body with the mbrt_body_fn signature; a table of them (an
// mbrt_program_table named by EmitOptions::tableName) and one C entry point
// per numbered program (`mbrt_status mbc_O1000(mbrt_ctx*, const mbrt_word*,
// size_t)`, which runs it as the main program) are what other code links to.
#pragma once

#include "codegen/object_options.h"
#include "ir/ir.h"

#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>

#include <memory>
#include <string>
#include <vector>

namespace mbc::codegen {

std::unique_ptr<llvm::Module> emitModule(const ir::Module& module,
                                         llvm::LLVMContext& context,
                                         const EmitOptions& options);

/// A program is compiled as at -O0 (see emit_module.cpp): its code
/// generator level must be None (optimize.h).
bool hasUnoptimizedBody(const ir::Module& module);

} // namespace mbc::codegen
