// Ahead-of-time compilation: an IR module to LLVM IR text, assembly or an
// ELF object for the host's architecture (generic CPU unless asked for
// another, position-independent so that it links into executables and
// shared libraries alike).
#pragma once

#include "codegen/emit_module.h"
#include "ir/ir.h"

#include <string>

namespace mbc::codegen {

enum class FileKind { LlvmIr, Assembly, Object };

struct ObjectOptions {
  EmitOptions emit;
  int optLevel = 2;
  /// The CPU to tune and select instructions for: "" for the architecture's
  /// generic one, "native" for this machine's.
  std::string cpu;
};

/// Writes `path` ("-" is standard output) through a temporary file renamed
/// into place, so that a failed compile leaves no half-written output.
/// False with the reason in `error`.
bool writeCompiled(const ir::Module& module, const ObjectOptions& options,
                   FileKind kind, const std::string& path, std::string& error);

} // namespace mbc::codegen
