// The code generator as a plugin: libmbc_codegen.so holds LLVM's half of
// mbc and is loaded only by commands that must generate code
// (toolchain/code_generator.h), so that the rest start without loading
// libLLVM. Both sides are built from the same tree with the same compiler:
// the interface passes C++ objects.
#pragma once

#include "codegen/object_options.h"
#include "ir/ir.h"

#include <string>

namespace mbc::codegen {

struct Plugin {
  /// writeCompiled (object_file.h).
  bool (*writeCompiled)(const ir::Module& module, const ObjectOptions& options,
                        FileKind kind, const std::string& path,
                        std::string& error);
};

/// The one symbol the plugin exports: `const Plugin* mbc_codegen_plugin()`.
inline constexpr char kPluginEntry[] = "mbc_codegen_plugin";

} // namespace mbc::codegen
