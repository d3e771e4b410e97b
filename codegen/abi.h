// The C ABI of the runtime as LLVM sees it: the struct types generated code
// builds or reads (mbrt_word, mbrt_print_item, mbrt_flow, mbrt_level,
// mbrt_block_state, mbrt_program, mbrt_nc_run) and the runtime functions of
// runtime_functions.def, declared in one module.
#pragma once

#include <llvm/IR/DerivedTypes.h>
#include <llvm/IR/Module.h>

#include <array>
#include <memory>

namespace mbc::codegen {

enum class Rt {
#define RT(Name, ...) Name,
#include "codegen/runtime_functions.def"
  Count
};

/// Field numbers of the struct types, in C declaration order.
enum WordField { kWordLetter, kWordKind, kWordValue };

enum PrintField { kItemText, kItemValue, kItemIntDigits, kItemFracDigits };

enum FlowField {
  kFlowKind,
  kFlowProgram,
  kFlowRepeat,
  kFlowHasSeq,
  kFlowSeq,
  kFlowCountsPart,
  kFlowCallKind,
  kFlowArgs,
  kFlowArgCount,
  kFlowStartSeq
};

enum LevelField { kLevelValue, kLevelAdpMask };

enum BlockField {
  kBlockFile,
  kBlockLine,
  kBlockTracing,
  kBlockCount,
  kBlockMax
};

/// A context whose pointers are opaque (LLVM 14 still defaults to typed
/// ones; later versions have only opaque pointers).
std::unique_ptr<llvm::LLVMContext> makeContext();

struct Abi {
  explicit Abi(llvm::Module& module);

  llvm::FunctionCallee fn(Rt f) const {
    return functions[static_cast<std::size_t>(f)];
  }

  llvm::Module& module;
  llvm::LLVMContext& context;
  llvm::Type* voidTy;
  llvm::IntegerType* i1;
  llvm::IntegerType* i8;
  llvm::IntegerType* i32;
  llvm::IntegerType* i64;
  llvm::Type* f64;
  llvm::PointerType* ptr;
  llvm::StructType* word;
  llvm::StructType* printItem;
  llvm::StructType* flow;
  llvm::StructType* level;
  llvm::StructType* blockState;
  llvm::StructType* program;
  llvm::StructType* table;
  llvm::StructType* ncRun;
  /// mbrt_body_fn: i32 (ptr ctx, ptr user, ptr leave).
  llvm::FunctionType* body;
  std::array<llvm::FunctionCallee, static_cast<std::size_t>(Rt::Count)>
      functions;
};

} // namespace mbc::codegen
