#include "driver/jit_compiler.h"

#include "driver/code_generator.h"
#include "driver/code_key.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace mbc::driver {

namespace {

void warn(const std::string& message) {
  std::fprintf(stderr, "mbc: warning: %s\n", message.c_str());
}

} // namespace

JitCompiler::JitCompiler(const Options& o, const SourceManager& sources)
    : options_(o) {
  if (o.noCache) {
    return;
  }
  std::string warning;
  cache_ = CodeCache::fromEnvironment(warning);
  if (!warning.empty()) {
    warn(warning);
  }
  if (cache_.enabled()) {
    key_ = codeKey(o, sources);
  }
}

std::unique_ptr<NativeCode> JitCompiler::cached() const {
  if (!cache_.enabled()) {
    return nullptr;
  }
  const std::string path = cache_.find(key_);
  if (path.empty()) {
    return nullptr;
  }
  std::string error;
  // An entry removed by another process since find() is compiled anew.
  return NativeCode::open(path, error);
}

std::unique_ptr<NativeCode> JitCompiler::compile(const ir::Module& module,
                                                 std::string& error) const {
  namespace fs = std::filesystem;
  std::string dir = (fs::temp_directory_path() / "mbc-jit-XXXXXX").string();
  if (mkdtemp(dir.data()) == nullptr) {
    error = "cannot create a temporary directory";
    return nullptr;
  }
  codegen::ObjectOptions opts;
  opts.emit.tableName = kLoadedTableName;
  opts.emit.entryPoints = false;
  opts.emit.debugInfo = options_.debugInfo;
  opts.optLevel = options_.optLevel;
  opts.sizeLevel = options_.sizeLevel;
  opts.cpu = "native";
  const std::string object = dir + "/code.o";
  std::string path = dir + "/code.so";
  std::unique_ptr<NativeCode> code;
  if (writeCompiled(module, opts, codegen::FileKind::Object, object, error) &&
      NativeCode::link(object, path, error)) {
    if (cache_.enabled()) {
      std::string why;
      if (std::string entry = cache_.publish(key_, path, why); !entry.empty()) {
        path = entry;
      } else {
        warn(why + "; the code is not cached");
      }
    }
    code = NativeCode::open(path, error);
  }
  // The loaded code stays mapped after its file is gone.
  std::error_code ec;
  fs::remove_all(dir, ec);
  return code;
}

} // namespace mbc::driver
