// While LLVM compiles, an allocation that fails ends the process with a
// message rather than an exception.
#pragma once

namespace mbc::codegen {

/// While one lives (in any thread), an allocation that fails prints
/// "mbc: error: out of memory" and exits with status 4 instead of throwing
/// std::bad_alloc. LLVM is built without exceptions and is not
/// exception-safe: an exception thrown by an allocation inside it runs the
/// cleanup of half-built objects and the destructors of half-updated ones,
/// which corrupts the heap or crashes (tests/oom). LLVM's own allocations
/// that fail end the process the same way (they would abort). Nothing a
/// run writes is lost: compiling comes before running.
class ExitOnOutOfMemory {
public:
  ExitOnOutOfMemory();
  ~ExitOnOutOfMemory();
  ExitOnOutOfMemory(const ExitOnOutOfMemory&) = delete;
  ExitOnOutOfMemory& operator=(const ExitOnOutOfMemory&) = delete;
};

} // namespace mbc::codegen
