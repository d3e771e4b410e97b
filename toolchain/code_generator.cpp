#include "toolchain/code_generator.h"

#include "codegen/plugin.h"

#include <dlfcn.h>

#include "toolchain/own_libraries.h"

namespace mbc::toolchain {

namespace {

struct Loaded {
  const codegen::Plugin* plugin = nullptr;
  std::string error;
};

// Once per process; the plugin stays loaded until the process ends (LLVM's
// globals are not made to be unloaded).
Loaded load() {
  Loaded loaded;
  const std::string& path = ownLibraries().codegen;
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    loaded.error = "cannot load the code generator: " +
                   std::string(why != nullptr ? why : path);
    return loaded;
  }
  using Entry = const codegen::Plugin* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, codegen::kPluginEntry));
  if (entry == nullptr) {
    loaded.error = "the code generator " + path + " has no " +
                   codegen::kPluginEntry + " (a library of another mbc?)";
    return loaded;
  }
  loaded.plugin = entry();
  return loaded;
}

} // namespace

codegen::ObjectOptions objectOptions(const CodeLevel& code,
                                     const std::string& cpu) {
  codegen::ObjectOptions opts;
  opts.emit.debugInfo = code.debugInfo;
  opts.optLevel = code.optLevel;
  opts.sizeLevel = code.sizeLevel;
  opts.cpu = cpu;
  return opts;
}

bool writeCompiled(const ir::Module& module,
                   const codegen::ObjectOptions& options,
                   codegen::FileKind kind, const std::string& path,
                   std::string& error) {
  static const Loaded loaded = load();
  if (loaded.plugin == nullptr) {
    error = loaded.error;
    return false;
  }
  return loaded.plugin->writeCompiled(module, options, kind, path, error);
}

} // namespace mbc::toolchain
