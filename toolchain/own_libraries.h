// Where mbc finds libraries of its own: the static libraries that `mbc
// build` and `mbc compile --shared` link, and the code generator it loads
// (codegen/plugin.h). Beside an installed mbc (<prefix>/bin/mbc,
// <prefix>/lib/libmbc_runtime.a, <prefix>/lib/mbc/libmbc_codegen.so), or in
// the build tree that made it.
#pragma once

#include <string>

namespace mbc::toolchain {

struct OwnLibraries {
  std::string runner;  // the run support of `mbc build` executables
  std::string runtime; // the C ABI runtime
  std::string codegen; // the code generator plugin
};

const OwnLibraries& ownLibraries();

} // namespace mbc::toolchain
