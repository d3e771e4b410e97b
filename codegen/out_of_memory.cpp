// The handlers of ExitOnOutOfMemory, installed while any guard lives.
#include "codegen/out_of_memory.h"

#include <llvm/Support/ErrorHandling.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <new>

namespace mbc::codegen {

namespace {

std::mutex gMutex;
int gGuards = 0;
std::new_handler gPrevious = nullptr;

[[noreturn]] void exitOutOfMemory() {
  std::fputs("mbc: error: out of memory\n", stderr);
  std::_Exit(4);
}

// LLVM's own allocations (safe_malloc) report here; it would abort.
[[noreturn]] void exitLlvmOutOfMemory(void*, const char*, bool) {
  exitOutOfMemory();
}

} // namespace

ExitOnOutOfMemory::ExitOnOutOfMemory() {
  std::lock_guard<std::mutex> lock(gMutex);
  if (gGuards++ == 0) {
    gPrevious = std::set_new_handler(&exitOutOfMemory);
    llvm::install_bad_alloc_error_handler(&exitLlvmOutOfMemory);
  }
}

ExitOnOutOfMemory::~ExitOnOutOfMemory() {
  std::lock_guard<std::mutex> lock(gMutex);
  if (--gGuards == 0) {
    std::set_new_handler(gPrevious);
    llvm::remove_bad_alloc_error_handler();
  }
}

} // namespace mbc::codegen
