// What the hand-written workloads share: a runtime context with no sinks,
// NC blocks sent the way compiled code sends them, and the same summary
// lines as `mbc run --time`, so bench/run.py reads them alike.
#pragma once

#include <mbc/engine.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>

namespace mbc::bench {

class HandRun {
public:
  HandRun() {
    char err[256];
    ctx_ = mbrt_create(nullptr, err, sizeof err);
    if (ctx_ == nullptr) {
      std::fprintf(stderr, "hand: %s\n", err);
      std::exit(2);
    }
    mbrt_start(ctx_, "MAIN");
    start_ = std::chrono::steady_clock::now();
  }

  ~HandRun() {
    const double ms = std::chrono::duration<double, std::milli>(
                          std::chrono::steady_clock::now() - start_)
                          .count();
    mbrt_stats stats{};
    mbrt_get_stats(ctx_, &stats);
    std::fprintf(stderr,
                 "hand: %llu blocks, %llu moves\nmbc: time: run %.3f ms\n",
                 static_cast<unsigned long long>(stats.blocks),
                 static_cast<unsigned long long>(stats.moves), ms);
    mbrt_destroy(ctx_);
  }

  HandRun(const HandRun&) = delete;
  HandRun& operator=(const HandRun&) = delete;

  /// One NC block: letters with computed values, as compiled code sends them.
  void block(std::initializer_list<mbrt_word> words) {
    mbrt_flow flow;
    if (mbrt_begin_block(ctx_, "hand", ++line_) != 0 ||
        mbrt_nc_block(ctx_, words.begin(), words.size(), &flow) != 0) {
      char report[512];
      mbrt_alarm_report(ctx_, report, sizeof report);
      std::fprintf(stderr, "hand: %s", report);
      std::exit(3);
    }
  }

private:
  mbrt_ctx* ctx_ = nullptr;
  std::chrono::steady_clock::time_point start_;
  int line_ = 0;
};

/// A word with a computed value (X[#5]): the kind compiled code sends.
inline mbrt_word w(char letter, double value) {
  return {letter, MBRT_WORD_VALUE, value};
}

} // namespace mbc::bench
