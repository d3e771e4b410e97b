#include "driver/version_text.h"

#include <mbc/version.h>

#include <fmt/format.h>

#include "build_info.h"
#include "build_paths.h"

namespace mbc::driver {

std::string versionText() {
  const std::string sanitizers = MBC_SANITIZE;
  return fmt::format(
      "mbc {}\nLLVM {}\nbuild type: {}{}\ntarget: {}\n", MBC_VERSION_STRING,
      MBC_LLVM_VERSION, MBC_BUILD_TYPE,
      sanitizers.empty() ? "" : " with sanitizers (" + sanitizers + ")",
      MBC_TARGET_TRIPLE);
}

} // namespace mbc::driver
