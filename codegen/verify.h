// The LLVM verifier over emitted code: a failure is an internal compiler
// error, reported with the verifier's words.
#pragma once

#include <llvm/IR/Module.h>

#include <string>

namespace mbc::codegen {

bool verifyEmitted(const llvm::Module& module, std::string& error);

} // namespace mbc::codegen
