#include "codegen/verify.h"

#include <llvm/IR/Verifier.h>
#include <llvm/Support/raw_ostream.h>

namespace mbc::codegen {

bool verifyEmitted(const llvm::Module& module, std::string& error) {
  llvm::raw_string_ostream out(error);
  if (!llvm::verifyModule(module, &out)) {
    return true;
  }
  out.flush();
  error = "invalid LLVM IR emitted: " + error;
  return false;
}

} // namespace mbc::codegen
