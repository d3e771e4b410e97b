// The code generator, loaded when the first piece of code must be generated
// (codegen/plugin.h): `mbc check`, the interpreter, the IR evaluator and
// compiled code found in the cache never load libLLVM.
#pragma once

#include "codegen/object_options.h"
#include "ir/ir.h"

#include <string>

#include "toolchain/request.h"

namespace mbc::toolchain {

/// The options of an object of `code`'s levels for `cpu` ("": generic,
/// "native": this machine's, or a name).
codegen::ObjectOptions objectOptions(const CodeLevel& code,
                                     const std::string& cpu);

/// codegen::writeCompiled (codegen/object_file.h) through the plugin. False
/// with the reason in `error`, also when the plugin cannot be loaded.
bool writeCompiled(const ir::Module& module,
                   const codegen::ObjectOptions& options,
                   codegen::FileKind kind, const std::string& path,
                   std::string& error);

} // namespace mbc::toolchain
