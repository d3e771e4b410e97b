// The C header `mbc compile --header` writes: the program table and one
// entry point per numbered program of the object.
#pragma once

#include "ir/ir.h"

#include <string>

namespace mbc::codegen {

/// `guard` is the include guard macro.
std::string cHeader(const ir::Module& module, const std::string& tableName,
                    const std::string& guard);

} // namespace mbc::codegen
