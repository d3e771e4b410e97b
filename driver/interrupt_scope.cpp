// The handlers of interrupt_scope.h. Only async-signal-safe work happens in
// the handler: lock-free atomic stores (mbrt_interrupt) and, for a second
// signal, restoring the default action and raising it again.
#include "driver/interrupt_scope.h"

#include <atomic>
#include <csignal>

namespace mbc::driver {
namespace {

std::atomic<mbrt_ctx*> running{nullptr};
std::atomic<int> caught{0};
constexpr int kSignals[] = {SIGINT, SIGTERM};
struct sigaction previous[2];

void onSignal(int sig) {
  if (caught.exchange(sig) != 0) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  if (mbrt_ctx* ctx = running.load()) {
    mbrt_interrupt(ctx);
  }
}

} // namespace

InterruptScope::InterruptScope(mbrt_ctx* ctx) {
  caught = 0;
  running = ctx;

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
  running = nullptr;
}

int InterruptScope::signal() {
  return caught;
}

} // namespace mbc::driver
