// The handlers of interrupt_scope.h. Only async-signal-safe work happens in
// the signal handler: lock-free atomic loads and stores (mbrt_interrupt)
// and, for a second signal, restoring the default action and raising it
// again.
#include "runner/interrupt_scope.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace mbc::runner {
namespace {

std::atomic<mbrt_ctx*> running[InterruptibleRun::kMaxRuns];
std::atomic<int> caught{0};
constexpr int kSignals[] = {SIGINT, SIGTERM};
struct sigaction previous[2];

void stopRuns(void (*stop)(mbrt_ctx*)) {
  for (std::atomic<mbrt_ctx*>& run : running) {
    if (mbrt_ctx* ctx = run.load()) {
      stop(ctx);
    }
  }
}

void onSignal(int sig) {
  if (caught.exchange(sig) != 0) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  stopRuns(&mbrt_interrupt);
}

// Enough for the block going on to end, the alarm, the outputs' last
// records and the state file.
constexpr std::size_t kReserveBytes = std::size_t{16} << 20;
std::atomic<void*> reserve{nullptr};
std::new_handler previousNewHandler = nullptr;

void onOutOfMemory() {
  if (void* memory = reserve.exchange(nullptr)) {
    std::free(memory);
    stopRuns(&mbrt_out_of_memory);
    return; // operator new tries again
  }
  std::fflush(nullptr);
  std::fputs("mbc: error: out of memory\n", stderr);
  std::_Exit(4);
}

} // namespace

InterruptScope::InterruptScope() {
  caught = 0;
  reserve = std::malloc(kReserveBytes);
  previousNewHandler = std::set_new_handler(&onOutOfMemory);

  struct sigaction action {};

  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int i = 0; i < 2; ++i) {
    sigaction(kSignals[i], &action, &previous[i]);
  }
}

InterruptScope::~InterruptScope() {
  for (int i = 0; i < 2; ++i) {
    sigaction(kSignals[i], &previous[i], nullptr);
  }
  std::set_new_handler(previousNewHandler);
  std::free(reserve.exchange(nullptr));
}

void interruptRuns() {
  stopRuns(&mbrt_interrupt);
}

int InterruptScope::signal() {
  return caught;
}

InterruptibleRun::InterruptibleRun(mbrt_ctx* ctx) {
  for (int i = 0; i < kMaxRuns && slot_ < 0; ++i) {
    mbrt_ctx* expected = nullptr;
    if (running[i].compare_exchange_strong(expected, ctx)) {
      slot_ = i;
    }
  }
  // The signal may have come before the slot was taken.
  if (caught != 0) {
    mbrt_interrupt(ctx);
  }
}

InterruptibleRun::~InterruptibleRun() {
  if (slot_ >= 0) {
    running[slot_] = nullptr;
  }
}

} // namespace mbc::runner
