// LLVM types and declarations of the runtime's C ABI (see abi.h).
#include "codegen/abi.h"

#include <mbc/compiled.h>
#include <mbc/engine.h>
#include <mbc/limits.h>

#include <llvm/Config/llvm-config.h>
#include <llvm/IR/LLVMContext.h>

#include <type_traits>

namespace mbc::codegen {

namespace {

enum class Kind { Void, I32, I64, F64, Ptr };

llvm::Type* typeOf(const Abi& abi, Kind k) {
  switch (k) {
    case Kind::Void:
      return abi.voidTy;
    case Kind::I32:
      return abi.i32;
    case Kind::I64:
      return abi.i64;
    case Kind::F64:
      return abi.f64;
    case Kind::Ptr:
      break;
  }
  return abi.ptr;
}

llvm::FunctionType* signature(const Abi& abi, Kind result,
                              std::initializer_list<Kind> params) {
  std::vector<llvm::Type*> types;
  for (Kind k : params) {
    types.push_back(typeOf(abi, k));
  }
  return llvm::FunctionType::get(typeOf(abi, result), types, false);
}

// Each row of runtime_functions.def against the runtime's own declaration:
// a parameter added, removed or retyped there fails the build here.
template <Kind K, class T> constexpr bool passesAs() {
  if constexpr (K == Kind::Void) {
    return std::is_void_v<T>;
  } else if constexpr (K == Kind::Ptr) {
    return std::is_pointer_v<T>;
  } else if constexpr (K == Kind::F64) {
    return std::is_same_v<T, double>;
  } else {
    return std::is_integral_v<T> && sizeof(T) == (K == Kind::I32 ? 4 : 8);
  }
}

template <Kind Result, Kind... Params, class R, class... Args>
constexpr bool declaredAs(R (*)(Args...)) {
  if constexpr (sizeof...(Params) != sizeof...(Args)) {
    return false;
  } else {
    return passesAs<Result, R>() && (passesAs<Params, Args>() && ...);
  }
}

using enum Kind;
#define RT(Name, Result, ...)                                                  \
  static_assert(declaredAs<Result, __VA_ARGS__>(&::Name),                      \
                #Name " differs from its row in runtime_functions.def");
#include "codegen/runtime_functions.def"

} // namespace

std::unique_ptr<llvm::LLVMContext> makeContext() {
  auto context = std::make_unique<llvm::LLVMContext>();
#if LLVM_VERSION_MAJOR < 15
  context->enableOpaquePointers();
#endif
  return context;
}

Abi::Abi(llvm::Module& m)
    : module(m), context(m.getContext()),
      voidTy(llvm::Type::getVoidTy(context)),
      i1(llvm::Type::getInt1Ty(context)), i8(llvm::Type::getInt8Ty(context)),
      i32(llvm::Type::getInt32Ty(context)),
      i64(llvm::Type::getInt64Ty(context)),
      f64(llvm::Type::getDoubleTy(context)),
      ptr(llvm::PointerType::get(context, 0)) {
  word = llvm::StructType::create(context, {i8, i8, f64}, "mbrt_word");
  printItem = llvm::StructType::create(context, {ptr, f64, i32, i32},
                                       "mbrt_print_item");
  flow = llvm::StructType::create(
      context, {i32, i32, i64, i32, f64, i32, i32, ptr, i64, f64}, "mbrt_flow");
  level = llvm::StructType::create(
      context, {llvm::ArrayType::get(f64, kLocalCount), i64}, "mbrt_level");
  blockState = llvm::StructType::create(context, {ptr, i32, i32, i64, i64},
                                        "mbrt_block_state");
  program = llvm::StructType::create(context, {ptr, i32, ptr}, "mbrt_program");
  table = llvm::StructType::create(context, {ptr, i64}, "mbrt_program_table");
  ncRun = llvm::StructType::create(context, {ptr, ptr, ptr, ptr, i64},
                                   "mbrt_nc_run");
  body = llvm::FunctionType::get(i32, {ptr, ptr, ptr}, false);
  using enum Kind;
#define RT(Name, Result, ...)                                                  \
  functions[static_cast<std::size_t>(Rt::Name)] = module.getOrInsertFunction(  \
      #Name, signature(*this, Result, {__VA_ARGS__}));
#include "codegen/runtime_functions.def"
}

} // namespace mbc::codegen
