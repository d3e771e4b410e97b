// The rows of a batch go to worker threads in table order, each worker with
// a context of its own, reset before every row; the main thread takes the
// finished rows back in table order, so that results.csv and the combined
// JSONL do not depend on the number of threads or on timing.
#include "driver/batch_command.h"

#include "driver/batch_progress.h"
#include "driver/batch_table.h"
#include "driver/interrupt_scope.h"
#include "driver/output_files.h"
#include "driver/prepared_program.h"
#include "driver/run_session.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <thread>

namespace mbc::driver {

namespace {

namespace fs = std::filesystem;

// Alarm reports shown on stderr; results.csv has them all.
constexpr std::size_t kShownAlarms = 10;
// How often the writer takes the rows finished meanwhile.
constexpr auto kTakeInterval = std::chrono::milliseconds(20);

struct RowResult {
  bool done = false;
  int exit = 0; // runSession's exit status
  std::string alarm;
  mbrt_stats stats{};
  std::string combined; // the row's line of the combined JSONL
};

/// What a row wrote: its files, or its line of the combined JSONL.
struct RowOutputs {
  std::string toolpath, dprnt, vars, log;
};

const char* statusName(const RowResult& r) {
  if (r.exit == 0) {
    return "ended";
  }
  if (r.exit == 3) {
    return r.alarm.find("MBC0004") != std::string::npos ? "interrupted"
                                                        : "alarm";
  }
  return r.exit > 128 ? "interrupted" : "error";
}

std::string csvQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    out += c == '"' ? "\"\"" : std::string(1, c);
  }
  return out + "\"";
}

// A row's file is written plainly, without replaceFile's fsync and
// rename: results.csv says which rows are complete.
bool writeWhole(const std::string& path, const std::string& content) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) {
    return false;
  }
  const bool ok =
      std::fwrite(content.data(), 1, content.size(), f) == content.size();
  return std::fclose(f) == 0 && ok;
}

std::string shardSuffix(const Shard& shard) {
  return shard.count == 1
             ? ""
             : fmt::format(".shard-{}-of-{}", shard.index, shard.count);
}

/// One line of the combined JSONL: everything a row's files would hold.
std::string combinedLine(const BatchRow& row, const RowResult& r,
                         const RowOutputs& out) {
  using nlohmann::json;
  const auto text = [](const std::string& s) {
    return json(s).dump(-1, ' ', false, json::error_handler_t::replace);
  };
  std::string vars = out.vars;
  while (!vars.empty() && vars.back() == '\n') {
    vars.pop_back();
  }
  std::string toolpath = out.toolpath;
  std::replace(toolpath.begin(), toolpath.end(), '\n', ',');
  if (!toolpath.empty()) {
    toolpath.pop_back();
  }
  return fmt::format(
      "{{\"row\":{},\"line\":{},\"status\":\"{}\",\"alarm\":{},"
      "\"blocks\":{},\"moves\":{},\"feed_length\":{:.3f},"
      "\"rapid_length\":{:.3f},\"cycle_time\":{:.1f},\"vars\":{},"
      "\"dprnt\":{},\"log\":{},\"toolpath\":[{}]}}\n",
      text(row.id), row.line, statusName(r),
      r.alarm.empty() ? "null" : text(r.alarm), r.stats.blocks, r.stats.moves,
      r.stats.feed_length, r.stats.rapid_length, r.stats.cycle_time,
      vars.empty() ? "{}" : vars, text(out.dprnt), text(out.log), toolpath);
}

class Batch {
public:
  Batch(const Options& o, const PreparedProgram& program,
        std::vector<BatchRow> rows)
      : o_(o), program_(program), rows_(std::move(rows)),
        results_(rows_.size()) {}

  /// Runs every row on `contexts.size()` threads; the caller's
  /// InterruptScope stops it. Calls `take` for each finished row in table
  /// order, on this thread, and `caughtUp` when it has taken every row
  /// finished so far, before it waits for more.
  template <typename Take, typename CaughtUp>
  void run(const std::vector<CtxPtr>& contexts, Take take, CaughtUp caughtUp) {
    std::vector<std::thread> workers;
    for (const CtxPtr& ctx : contexts) {
      workers.emplace_back([this, c = ctx.get()] { work(c); });
    }
    std::size_t next = 0;
    while (next < rows_.size()) {
      bool allIdle = false;
      {
        // Woken when the workers are done, else every kTakeInterval: a
        // wake-up per row cost more than the rows themselves.
        std::unique_lock lock(mutex_);
        allIdle = changed_.wait_for(lock, kTakeInterval,
                                    [&] { return idle_ == workers.size(); });
      }
      while (next < rows_.size() && isDone(next)) {
        take(rows_[next], results_[next]);
        std::string().swap(results_[next].combined);
        ++next;
      }
      caughtUp();
      if (allIdle) {
        break; // every row taken, or interrupted: the rest never ran
      }
    }
    for (std::thread& w : workers) {
      w.join();
    }
  }

  std::size_t size() const { return rows_.size(); }

private:
  bool isDone(std::size_t i) {
    std::lock_guard lock(mutex_);
    return results_[i].done;
  }

  void work(mbrt_ctx* ctx) {
    while (true) {
      const std::size_t i = next_++;
      if (i >= rows_.size() || InterruptScope::signal() != 0) {
        break;
      }
      RowResult r = runRow(rows_[i], ctx);
      r.done = true;
      std::lock_guard lock(mutex_);
      results_[i] = std::move(r);
    }
    std::lock_guard lock(mutex_);
    ++idle_;
    changed_.notify_one();
  }

  RowResult runRow(const BatchRow& row, mbrt_ctx* ctx) const {
    RunOptions ro = o_.run;
    ro.presets.insert(ro.presets.end(), row.presets.begin(), row.presets.end());
    for (const auto& [letter, value] : row.args) {
      auto same = std::find_if(ro.args.begin(), ro.args.end(),
                               [l = letter](auto& a) { return a.first == l; });
      if (same != ro.args.end()) {
        same->second = value;
      } else {
        ro.args.emplace_back(letter, value);
      }
    }
    RowResult r;
    OutputFile text;
    SessionLog log;
    log.capture = true;
    if (!text.openMemory()) {
      std::fputs("mbc: error: out of memory\n", stderr);
      r.exit = 2;
      return r;
    }
    log.text = text.get();
    mbrt_reset(ctx);
    r.exit = runSession(
        ro, ctx, program_.mainName(),
        [this](mbrt_ctx* c) { return program_.run(c); }, log);
    text.finish();
    r.alarm = std::move(log.alarm);
    r.stats = log.stats;
    const RowOutputs out{std::move(log.toolpath), std::move(log.dprnt),
                         std::move(log.vars), text.takeMemory()};
    // The line is made here, on the row's thread, not by the one writer.
    if (o_.combined) {
      r.combined = combinedLine(row, r, out);
      return r;
    }
    const std::string base = (fs::path(o_.outDir) / row.id).string();
    const std::pair<const char*, const std::string*> files[] = {
        {".toolpath.jsonl", &out.toolpath},
        {".dprnt", &out.dprnt},
        {".vars.json", &out.vars},
        {".log", &out.log}};
    for (const auto& [ext, content] : files) {
      if (!writeWhole(base + ext, *content)) {
        std::fprintf(stderr, "mbc: error: cannot write '%s%s': %s\n",
                     base.c_str(), ext, std::strerror(errno));
        r.exit = 2;
      }
    }
    return r;
  }

  const Options& o_;
  const PreparedProgram& program_;
  std::vector<BatchRow> rows_;
  std::vector<RowResult> results_;
  std::atomic<std::size_t> next_{0};
  std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t idle_ = 0;
};

} // namespace

int batchCommand(const Options& o) {
  std::vector<BatchRow> all;
  std::string error;
  Shard shard;
  if (!parseShard(o.shard.empty() ? "0/1" : o.shard, shard)) {
    std::fprintf(stderr,
                 "mbc: error: --shard expects I/N with 0 <= I < N, got '%s'\n",
                 o.shard.c_str());
    return 2;
  }
  if (!readBatchTable(o.paramsPath, all, error)) {
    std::fprintf(stderr, "mbc: error: %s\n", error.c_str());
    return 2;
  }
  std::vector<BatchRow> rows;
  for (std::size_t i = static_cast<std::size_t>(shard.index); i < all.size();
       i += static_cast<std::size_t>(shard.count)) {
    rows.push_back(std::move(all[i]));
  }
  PhaseTimes phases;
  PreparedProgram program;
  if (int status = program.prepare(o, phases)) {
    return status == PreparedProgram::kNothingToRun ? 0 : status;
  }
  std::error_code ec;
  fs::create_directories(o.outDir, ec);
  if (ec) {
    std::fprintf(stderr, "mbc: error: cannot create '%s': %s\n",
                 o.outDir.c_str(), ec.message().c_str());
    return 2;
  }
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::clamp<std::size_t>(
      o.jobs > 0 ? static_cast<std::size_t>(o.jobs) : cores, 1,
      std::min<std::size_t>(std::max<std::size_t>(rows.size(), 1),
                            InterruptibleRun::kMaxRuns));
  std::vector<CtxPtr> contexts;
  for (std::size_t t = 0; t < threads; ++t) {
    contexts.push_back(createContext(o.run));
    if (!contexts.back()) {
      return 2;
    }
  }

  const std::string suffix = shardSuffix(shard);
  const std::string resultsPath =
      (fs::path(o.outDir) / ("results" + suffix + ".csv")).string();
  const std::string combinedPath =
      (fs::path(o.outDir) / ("batch" + suffix + ".jsonl")).string();
  OutputFile results, combined;
  if (!results.open(resultsPath) ||
      (o.combined && !combined.open(combinedPath))) {
    std::fprintf(stderr, "mbc: error: cannot write in '%s'\n",
                 o.outDir.c_str());
    return 2;
  }
  const char* header =
      "row,line,status,blocks,moves,feed_length,rapid_length,cycle_time,"
      "alarm\n";
  OutputFile::writeText(&results, header, std::strlen(header));

  ProgressLine progress(rows.size());
  std::size_t taken = 0, ended = 0, alarms = 0, errors = 0, interrupted = 0;
  const auto start = std::chrono::steady_clock::now();
  Batch batch(o, program, std::move(rows));
  {
    const InterruptScope interrupts;
    batch.run(
        contexts,
        [&](const BatchRow& row, const RowResult& r) {
          ++taken;
          ended += r.exit == 0;
          errors += r.exit == 2;
          interrupted += std::strcmp(statusName(r), "interrupted") == 0;
          if (r.exit == 3) {
            if (++alarms <= kShownAlarms) {
              progress.print(fmt::format("mbc: batch: row {} ({}:{}): {}",
                                         row.id, o.paramsPath, row.line,
                                         r.alarm));
            } else if (alarms == kShownAlarms + 1) {
              progress.print(fmt::format(
                  "mbc: batch: more alarms follow; {} lists every row",
                  resultsPath));
            }
          }
          const std::string line = fmt::format(
              "{},{},{},{},{},{:.3f},{:.3f},{:.1f},{}\n", row.id, row.line,
              statusName(r), r.stats.blocks, r.stats.moves, r.stats.feed_length,
              r.stats.rapid_length, r.stats.cycle_time,
              r.alarm.empty() ? "" : csvQuoted(r.alarm));
          OutputFile::writeText(&results, line.data(), line.size());
          if (o.combined) {
            OutputFile::writeText(&combined, r.combined.data(),
                                  r.combined.size());
          }
          progress.update(taken, alarms);
        },
        [&] {
          // Whole rows on disk as they come, for whoever follows the batch.
          std::fflush(results.get());
          if (o.combined) {
            std::fflush(combined.get());
          }
        });
  }
  progress.clear();
  bool written = true;
  for (OutputFile* out : {&results, &combined}) {
    if (!out->finish()) {
      std::fprintf(stderr, "mbc: error: cannot write '%s': %s\n",
                   out->path().c_str(), std::strerror(errno));
      written = false;
    }
  }
  const double seconds = millisecondsSince(start) / 1000.0;
  const std::string of =
      shard.count == 1 ? fmt::format("{} rows", taken)
                       : fmt::format("{} rows (shard {}/{} of {} rows)", taken,
                                     shard.index, shard.count, all.size());
  std::string others =
      errors ? fmt::format(", {} with lost output", errors) : "";
  if (interrupted) {
    others += fmt::format(", {} interrupted", interrupted);
  }
  std::fprintf(stderr,
               "mbc: batch: %s in %.2f s on %zu thread%s (%.0f rows/s): %zu "
               "ended, %zu alarm%s%s; %s\n",
               of.c_str(), seconds, threads, threads == 1 ? "" : "s",
               seconds > 0 ? static_cast<double>(taken) / seconds : 0.0, ended,
               alarms, alarms == 1 ? "" : "s", others.c_str(),
               (o.combined ? combinedPath : resultsPath).c_str());
  if (const int sig = InterruptScope::signal()) {
    std::fprintf(stderr,
                 "mbc: batch: interrupted; %zu of the rows did not "
                 "run\n",
                 batch.size() - taken);
    return 128 + sig;
  }
  if (!written || errors) {
    return 2;
  }
  return alarms ? 3 : 0;
}

} // namespace mbc::driver
