// SIGINT and SIGTERM during a run: the run stops before its next block with
// alarm MBC0004, so that its outputs end with whole records, are flushed, and
// the state file is saved as after an alarm. A second signal ends the
// process at once, as it would have without mbc's handler.
#pragma once

#include <mbc/runtime.h>

namespace mbc::driver {

class InterruptScope {
public:
  /// Installs the handlers for a run of `ctx`; the destructor restores the
  /// previous ones.
  explicit InterruptScope(mbrt_ctx* ctx);
  ~InterruptScope();

  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  /// The signal that interrupted the run, 0 if none came.
  static int signal();
};

} // namespace mbc::driver
