// What `mbc --version` says: mbc's version and what it was built with.
#pragma once

#include <string>

namespace mbc::driver {

/// Several lines: the version, the LLVM version the code generator is
/// built on, the build type and the target code is compiled for.
std::string versionText();

} // namespace mbc::driver
