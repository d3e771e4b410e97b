// The rows of a batch on worker threads: each worker has a context of its
// own, reset before every row, and all share one compiled program; rows
// are handed out in table order and given back in table order, so that
// what a batch writes does not depend on the number of threads or on
// timing.
#pragma once

#include "driver/batch_table.h"
#include "driver/options.h"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "runner/run_session.h"
#include "toolchain/prepared_program.h"

namespace mbc::driver {

/// What the writer learns of a finished row.
struct RowResult {
  bool done = false;
  int exit = 0; // runner::runSession's exit status
  std::string alarm;
  mbrt_stats stats{};
  std::string combined; // the row's line of the combined JSONL
};

/// "ended", "alarm", "interrupted" or "error" (an output was lost).
const char* statusName(const RowResult& r);

class BatchRunner {
public:
  using Take = std::function<void(const BatchRow&, const RowResult&)>;
  using CaughtUp = std::function<void()>;

  /// Rows write their files under o.outDir, or with o.combined make their
  /// line of the combined JSONL.
  BatchRunner(const Options& o, const toolchain::PreparedProgram& program,
              std::vector<BatchRow> rows)
      : o_(o), program_(program), rows_(std::move(rows)),
        results_(rows_.size()) {}

  /// Runs every row on `contexts.size()` threads; the caller's
  /// InterruptScope stops it. Calls `take` for each finished row in table
  /// order, on this thread, and `caughtUp` when it has taken every row
  /// finished so far, before it waits for more.
  void run(const std::vector<runner::CtxPtr>& contexts, const Take& take,
           const CaughtUp& caughtUp);

  std::size_t size() const { return rows_.size(); }

private:
  bool isDone(std::size_t i);
  void work(mbrt_ctx* ctx);
  RowResult runRow(const BatchRow& row, mbrt_ctx* ctx) const;

  const Options& o_;
  const toolchain::PreparedProgram& program_;
  std::vector<BatchRow> rows_;
  std::vector<RowResult> results_;
  std::atomic<std::size_t> next_{0};
  std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t idle_ = 0;
};

} // namespace mbc::driver
