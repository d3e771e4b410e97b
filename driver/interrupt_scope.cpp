// The handlers of interrupt_scope.h. Only async-signal-safe work happens in
// the handler: lock-free atomic loads and stores (mbrt_interrupt) and, for
// a second signal, restoring the default action and raising it again.
#include "driver/interrupt_scope.h"

#include <atomic>
#include <csignal>

namespace mbc::driver {
namespace {

std::atomic<mbrt_ctx*> running[InterruptibleRun::kMaxRuns];
std::atomic<int> caught{0};
constexpr int kSignals[] = {SIGINT, SIGTERM};
struct sigaction previous[2];

void onSignal(int sig) {
  if (caught.exchange(sig) != 0) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  for (std::atomic<mbrt_ctx*>& run : running) {
    if (mbrt_ctx* ctx = run.load()) {
      mbrt_interrupt(ctx);
    }
  }
}

} // namespace

InterruptScope::InterruptScope() {
  caught = 0;

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

} // namespace mbc::driver
