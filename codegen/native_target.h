// LLVM's registration of the host target, done once per process for the
// JIT and for object files alike.
#pragma once

namespace mbc::codegen {

void initializeNativeTarget();

} // namespace mbc::codegen
