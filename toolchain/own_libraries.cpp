// The installed libraries win over the build tree's: an installed mbc must
// not depend on a build directory that may be gone or rebuilt with other
// options.
#include "toolchain/own_libraries.h"

#include <dlfcn.h>
#include <filesystem>
#include <optional>
#include <system_error>

#include "build_paths.h"

namespace mbc::toolchain {

namespace {

/// The libraries installed in `dir` (<prefix>/lib), when they all are.
std::optional<OwnLibraries> installedIn(const std::filesystem::path& dir) {
  std::error_code ec;
  OwnLibraries installed{(dir / MBC_RUNNER_LIB_NAME).string(),
                         (dir / MBC_RUNTIME_LIB_NAME).string(),
                         (dir / "mbc" / MBC_CODEGEN_PLUGIN_NAME).string()};
  if (std::filesystem::is_regular_file(installed.runner, ec) &&
      std::filesystem::is_regular_file(installed.runtime, ec) &&
      std::filesystem::is_regular_file(installed.codegen, ec)) {
    return installed;
  }
  return std::nullopt;
}

/// Installed beside the mbc command (<prefix>/bin/mbc) or beside the
/// Python package's extension, the object this code is linked into.
OwnLibraries find() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    if (auto found = installedIn(
            (self.parent_path() / MBC_INSTALLED_LIB_DIR).lexically_normal())) {
      return *found;
    }
  }
  Dl_info object{};
  if (dladdr(reinterpret_cast<void*>(&installedIn), &object) != 0 &&
      object.dli_fname != nullptr) {
    const fs::path module = fs::absolute(object.dli_fname, ec);
    if (auto found = installedIn(
            (module.parent_path() / MBC_PYTHON_LIB_DIR).lexically_normal())) {
      return *found;
    }
  }
  return {MBC_RUNNER_LIB, MBC_RUNTIME_LIB, MBC_CODEGEN_PLUGIN};
}

} // namespace

const OwnLibraries& ownLibraries() {
  static const OwnLibraries libraries = find();
  return libraries;
}

} // namespace mbc::toolchain
