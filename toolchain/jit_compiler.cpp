#include "toolchain/jit_compiler.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "toolchain/code_generator.h"
#include "toolchain/code_key.h"

namespace mbc::toolchain {

namespace {

void warn(const std::string& message) {
  std::fprintf(stderr, "mbc: warning: %s\n", message.c_str());
}

} // namespace

JitCompiler::JitCompiler(const Request& r, const SourceManager& sources)
    : code_(r.code) {
  if (!r.useCache) {
    return;
  }
  std::string warning;
  cache_ = CodeCache::fromEnvironment(warning);
  if (!warning.empty()) {
    warn(warning);
  }
  if (cache_.enabled()) {
    key_ = codeKey(r, sources);
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
  codegen::ObjectOptions opts = objectOptions(code_, "native");
  opts.emit.tableName = kLoadedTableName;
  opts.emit.entryPoints = false;
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

} // namespace mbc::toolchain
