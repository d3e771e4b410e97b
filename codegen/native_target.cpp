#include "codegen/native_target.h"

#include <llvm/Support/TargetSelect.h>

#include <mutex>

namespace mbc::codegen {

void initializeNativeTarget() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
    llvm::InitializeNativeTargetAsmParser();
  });
}

} // namespace mbc::codegen
