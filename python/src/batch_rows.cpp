#include "batch_rows.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "runner/interrupt_scope.h"
#include "runner/run_session.h"

namespace mbc::python {

bool runRows(const CompiledProgram& program, const std::string* profile,
             const std::vector<RunRequest>& rows, unsigned threads,
             std::vector<std::unique_ptr<RunOutput>>& out, std::string& error) {
  threads = static_cast<unsigned>(
      std::max<std::size_t>(1, std::min<std::size_t>(threads, rows.size())));
  std::vector<runner::CtxPtr> contexts;
  for (unsigned i = 0; i < threads; ++i) {
    contexts.push_back(newContext(profile, error));
    if (!contexts.back()) {
      return false;
    }
  }
  out.clear();
  out.resize(rows.size());
  const std::string axes = axisNames(contexts.front().get());
  std::atomic<std::size_t> next{0};
  // A worker's rows number program and file names in its own tables.
  std::vector<NameTable> programs(threads), files(threads);
  const auto work = [&](unsigned worker) {
    mbrt_ctx* ctx = contexts[worker].get();
    for (std::size_t i = next++; i < rows.size(); i = next++) {
      mbrt_reset(ctx);
      out[i] =
          std::make_unique<RunOutput>(axes, programs[worker], files[worker]);
      const runner::InterruptibleRun interruptible(ctx);
      runProgram(program, ctx, rows[i], *out[i]);
      if (out[i]->status == MBRT_ALARM_Interrupted) {
        next = rows.size(); // Ctrl-C: no more rows
      }
    }
  };
  std::vector<std::thread> workers;
  for (unsigned i = 1; i < threads; ++i) {
    workers.emplace_back(work, i);
  }
  work(0);
  for (std::thread& worker : workers) {
    worker.join();
  }
  return true;
}

} // namespace mbc::python
