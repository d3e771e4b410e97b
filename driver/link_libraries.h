// Where `mbc build` and `mbc compile --shared` find the static libraries
// they link: beside an installed mbc (<prefix>/bin/mbc and
// <prefix>/lib/libmbc_runtime.a), or in the build tree that made it.
#pragma once

#include <string>

namespace mbc::driver {

struct LinkLibraries {
  std::string runner;  // the run support of `mbc build` executables
  std::string runtime; // the C ABI runtime
};

LinkLibraries linkLibraries();

} // namespace mbc::driver
