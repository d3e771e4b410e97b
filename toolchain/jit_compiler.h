// The code of `--engine jit`: generated for this machine's CPU, linked into
// a shared object and loaded (native_code.h), through the cache of
// compiled code (code_cache.h) unless --no-cache.
#pragma once

#include "frontend/source.h"
#include "ir/ir.h"

#include <memory>
#include <string>

#include "toolchain/code_cache.h"
#include "toolchain/native_code.h"
#include "toolchain/request.h"

namespace mbc::toolchain {

class JitCompiler {
public:
  /// For the input of `r` read into `sources`. A cache that cannot be used
  /// is a warning on standard error, not a failure.
  JitCompiler(const Request& r, const SourceManager& sources);

  /// The cached code of the input, or nullptr.
  std::unique_ptr<NativeCode> cached() const;

  /// Generates the code of `module` (the input's IR) and caches it.
  /// Nullptr with the reason in `error`.
  std::unique_ptr<NativeCode> compile(const ir::Module& module,
                                      std::string& error) const;

private:
  CodeLevel code_;
  CodeCache cache_{"", 0};
  std::string key_;
};

} // namespace mbc::toolchain
