// In-process compilation (`mbc run --engine jit`): an IR module compiled by
// ORC LLJIT for the host CPU, its programs callable through the runtime's
// program table.
#pragma once

#include "ir/ir.h"
#include <mbc/runtime.h>

#include <memory>
#include <string>

namespace llvm::orc {
class LLJIT;
}

namespace mbc::codegen {

struct JitOptions {
  int optLevel = 2; // 0..3
  /// DWARF line tables, registered with gdb's JIT interface so that a
  /// debugger attached to `mbc run` sees the .nc lines.
  bool debugInfo = false;
};

class Jit {
public:
  ~Jit();

  /// Compiles `module`. Returns nullptr with the reason in `error` when
  /// LLVM fails.
  static std::unique_ptr<Jit> compile(const ir::Module& module,
                                      const JitOptions& options,
                                      std::string& error);

  /// The compiled programs, valid while this object lives.
  const mbrt_program_table* programs() const { return table_; }

private:
  Jit() = default;

  std::unique_ptr<llvm::orc::LLJIT> jit_;
  const mbrt_program_table* table_ = nullptr;
};

} // namespace mbc::codegen
