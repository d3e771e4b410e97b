// The key of compiled code in the cache (code_cache.h): a hash of all that
// the code depends on, so that equal keys mean interchangeable code.
#pragma once

#include "frontend/source.h"

#include <string>

#include "toolchain/request.h"

namespace mbc::toolchain {

/// 32 hex digits (XXH3, 128 bits) of: the bytes and names of every source
/// file the unit was read from (the names are in alarm messages), the
/// options that change the code (optimisation, -g and then the working
/// folder its DWARF names, IR passes, --trace, how errors in the input
/// are handled), the build of mbc that generates it (its executable's
/// build ID and the code generator plugin's file), and this machine's CPU
/// (the code is compiled for it). The machine profile is not in it: code
/// reads its machine when it runs.
std::string codeKey(const Request& r, const SourceManager& sources);

} // namespace mbc::toolchain
