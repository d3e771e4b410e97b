// `mbc batch` (see batch_command.h): the table and its shard, the program
// compiled once, a context per thread, then the rows through BatchRunner,
// whose finished rows this writes to results.csv (and the combined JSONL)
// in table order, reporting alarms and progress, and a summary.
#include "driver/batch_command.h"

#include "driver/batch_outputs.h"
#include "driver/batch_progress.h"
#include "driver/batch_runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <thread>

#include "runner/interrupt_scope.h"
#include "runner/output_files.h"

namespace mbc::driver {

namespace {

namespace fs = std::filesystem;

// Alarm reports shown on stderr; results.csv has them all.
constexpr std::size_t kShownAlarms = 10;

std::string csvQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    out += c == '"' ? "\"\"" : std::string(1, c);
  }
  return out + "\"";
}

std::string shardSuffix(const Shard& shard) {
  return shard.count == 1
             ? ""
             : fmt::format(".shard-{}-of-{}", shard.index, shard.count);
}

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
  if (!readBatchTable(o.paramsPath, o.columnMap, all, error)) {
    // One line per problem: a header may have several.
    std::istringstream problems(error);
    for (std::string line; std::getline(problems, line);) {
      std::fprintf(stderr, "mbc: error: %s\n", line.c_str());
    }
    return 2;
  }
  std::vector<BatchRow> rows;
  for (std::size_t i = static_cast<std::size_t>(shard.index); i < all.size();
       i += static_cast<std::size_t>(shard.count)) {
    rows.push_back(all[i]);
  }
  runner::PhaseTimes phases;
  toolchain::PreparedProgram program;
  if (int status = program.prepare(toolchainRequest(o), phases)) {
    return status == toolchain::PreparedProgram::kNothingToRun ? 0 : status;
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
                            runner::InterruptibleRun::kMaxRuns));
  std::vector<runner::CtxPtr> contexts;
  for (std::size_t t = 0; t < threads; ++t) {
    contexts.push_back(runner::createContext(o.run));
    if (!contexts.back()) {
      return 2;
    }
  }

  const std::string suffix = shardSuffix(shard);
  const std::string resultsName = "results" + suffix + ".csv";
  const std::string combinedName = "batch" + suffix + ".jsonl";
  const std::string resultsPath = (fs::path(o.outDir) / resultsName).string();
  const std::string combinedPath = (fs::path(o.outDir) / combinedName).string();
  const FinishedRows finished =
      o.resume ? finishedRows(rows, resultsPath, o.combined ? combinedPath : "")
               : FinishedRows{};
  removeStaleOutputs(o.outDir, all, rows, finished.count, resultsName,
                     combinedName, o.combined);
  rows.erase(rows.begin(),
             rows.begin() + static_cast<std::ptrdiff_t>(finished.count));
  runner::OutputFile results, combined;
  if (!results.open(resultsPath) ||
      (o.combined && !combined.open(combinedPath))) {
    std::fprintf(stderr, "mbc: error: cannot write in '%s'\n",
                 o.outDir.c_str());
    return 2;
  }
  const std::string header =
      "id,line,status,blocks,moves,feed_length,rapid_length,cycle_time,"
      "alarm\n" +
      finished.results;
  runner::OutputFile::writeText(&results, header.data(), header.size());
  if (o.combined) {
    runner::OutputFile::writeText(&combined, finished.combined.data(),
                                  finished.combined.size());
  }

  ProgressLine progress(rows.size());
  std::size_t taken = 0, ended = 0, alarms = 0, errors = 0, interrupted = 0;
  const auto start = std::chrono::steady_clock::now();
  BatchRunner batch(o, program, std::move(rows));
  {
    const runner::InterruptScope interrupts;
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
          runner::OutputFile::writeText(&results, line.data(), line.size());
          if (o.combined) {
            runner::OutputFile::writeText(&combined, r.combined.data(),
                                          r.combined.size());
          }
          progress.update(taken, alarms);
        },
        [&] {
          // Whole rows on disk as they come, for whoever follows the batch.
          results.flush();
          if (o.combined) {
            combined.flush();
          }
        });
  }
  progress.clear();
  bool written = true;
  for (runner::OutputFile* out : {&results, &combined}) {
    if (!out->finish()) {
      std::fprintf(stderr, "mbc: error: cannot write '%s': %s\n",
                   out->path().c_str(), std::strerror(errno));
      written = false;
    }
  }
  const double seconds = runner::millisecondsSince(start) / 1000.0;
  // The rows an earlier batch finished count as this one's.
  ended += finished.count - finished.alarms;
  alarms += finished.alarms;
  const std::string kept =
      finished.count > 0
          ? fmt::format(", {} kept from the earlier batch", finished.count)
          : "";
  const std::string of =
      shard.count == 1 ? fmt::format("{} rows{}", taken + finished.count, kept)
                       : fmt::format("{} rows (shard {}/{} of {} rows{})",
                                     taken + finished.count, shard.index,
                                     shard.count, all.size(), kept);
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
  if (const int sig = runner::InterruptScope::signal()) {
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
