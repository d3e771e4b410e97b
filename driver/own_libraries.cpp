// The installed libraries win over the build tree's: an installed mbc must
// not depend on a build directory that may be gone or rebuilt with other
// options.
#include "driver/own_libraries.h"

#include <filesystem>
#include <system_error>

#include "build_paths.h"

namespace mbc::driver {

namespace {

OwnLibraries find() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path dir =
        (self.parent_path() / MBC_INSTALLED_LIB_DIR).lexically_normal();
    OwnLibraries installed{(dir / MBC_RUNNER_LIB_NAME).string(),
                           (dir / MBC_RUNTIME_LIB_NAME).string(),
                           (dir / "mbc" / MBC_CODEGEN_PLUGIN_NAME).string()};
    if (fs::is_regular_file(installed.runner, ec) &&
        fs::is_regular_file(installed.runtime, ec) &&
        fs::is_regular_file(installed.codegen, ec)) {
      return installed;
    }
  }
  return {MBC_RUNNER_LIB, MBC_RUNTIME_LIB, MBC_CODEGEN_PLUGIN};
}

} // namespace

const OwnLibraries& ownLibraries() {
  static const OwnLibraries libraries = find();
  return libraries;
}

} // namespace mbc::driver
