// Ahead-of-time compilation: an IR module to LLVM IR text, assembly or an
// ELF object for the host's architecture (generic CPU unless asked for
// another, position-independent so that it links into executables and
// shared libraries alike).
#pragma once

#include "codegen/object_options.h"
#include "ir/ir.h"

#include <string>

namespace mbc::codegen {

/// Writes `path` ("-" is standard output) through a temporary file renamed
/// into place, so that a failed compile leaves no half-written output.
/// False with the reason in `error`.
bool writeCompiled(const ir::Module& module, const ObjectOptions& options,
                   FileKind kind, const std::string& path, std::string& error);

} // namespace mbc::codegen
