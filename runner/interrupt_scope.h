// SIGINT and SIGTERM during a run or a batch of runs: every run going on
// stops before its next block with alarm MBC0004, so that its outputs end
// with whole records, are flushed, and the state file is saved as after an
// alarm; a batch starts no more rows. A second signal ends the process at
// once, as it would have without mbc's handler.
//
// Memory running out is handled the same way, with alarm MBC0005: a
// std::bad_alloc cannot be thrown through compiled code (it has no unwind
// tables; the process would abort), so an allocation that fails frees a
// reserve for the block going on and stops the runs. If memory runs out
// again, the outputs are flushed and mbc exits with status 4.
#pragma once

#include <mbc/runtime.h>

namespace mbc::runner {

/// The handlers (signals and the new-handler), installed for the scope's
/// lifetime; the destructor restores the previous ones. The contexts of the
/// runs it stops must outlive it.
class InterruptScope {
public:
  InterruptScope();
  ~InterruptScope();

  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  /// The signal that came during the scope, 0 if none.
  static int signal();
};

/// Stops every run registered by an InterruptibleRun before its next block
/// (alarm MBC0004), as a signal inside an InterruptScope does: for a host's
/// own signal handler (the Python package's). Async-signal-safe.
void interruptRuns();

/// One run that a signal stops, from after its context was started to its
/// end. Up to kMaxRuns at once (the threads of a batch); a run registered
/// after the signal stops at its first block.
class InterruptibleRun {
public:
  static constexpr int kMaxRuns = 256;

  explicit InterruptibleRun(mbrt_ctx* ctx);
  ~InterruptibleRun();

  InterruptibleRun(const InterruptibleRun&) = delete;
  InterruptibleRun& operator=(const InterruptibleRun&) = delete;

private:
  int slot_ = -1;
};

} // namespace mbc::runner
