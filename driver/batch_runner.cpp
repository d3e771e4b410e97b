// See batch_runner.h.
#include "driver/batch_runner.h"

#include "driver/batch_outputs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include "runner/interrupt_scope.h"
#include "runner/output_files.h"

namespace mbc::driver {

namespace {

namespace fs = std::filesystem;

// How often the writer takes the rows finished meanwhile.
constexpr auto kTakeInterval = std::chrono::milliseconds(20);

/// What a row wrote: its files, or its line of the combined JSONL.
struct RowOutputs {
  std::string toolpath, dprnt, vars, log;
};

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
      "{{\"id\":{},\"line\":{},\"status\":\"{}\",\"alarm\":{},"
      "\"blocks\":{},\"moves\":{},\"feed_length\":{:.3f},"
      "\"rapid_length\":{:.3f},\"cycle_time\":{:.1f},\"variables\":{},"
      "\"dprnt\":{},\"log\":{},\"toolpath\":[{}]}}\n",
      text(row.id), row.line, statusName(r),
      r.alarm.empty() ? "null" : text(r.alarm), r.stats.blocks, r.stats.moves,
      r.stats.feed_length, r.stats.rapid_length, r.stats.cycle_time,
      vars.empty() ? "{}" : vars, text(out.dprnt), text(out.log), toolpath);
}

} // namespace

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

void BatchRunner::run(const std::vector<runner::CtxPtr>& contexts,
                      const Take& take, const CaughtUp& caughtUp) {
  std::vector<std::thread> workers;
  for (const runner::CtxPtr& ctx : contexts) {
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

bool BatchRunner::isDone(std::size_t i) {
  std::lock_guard lock(mutex_);
  return results_[i].done;
}

void BatchRunner::work(mbrt_ctx* ctx) {
  while (true) {
    const std::size_t i = next_++;
    if (i >= rows_.size() || runner::InterruptScope::signal() != 0) {
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

RowResult BatchRunner::runRow(const BatchRow& row, mbrt_ctx* ctx) const {
  runner::RunOptions ro = o_.run;
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
  runner::OutputFile text;
  runner::SessionLog log;
  log.capture = true;
  if (!text.openMemory()) {
    std::fputs("mbc: error: out of memory\n", stderr);
    r.exit = 2;
    return r;
  }
  log.text = text.get();
  mbrt_reset(ctx);
  r.exit = runner::runSession(
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
  const std::string* contents[] = {&out.toolpath, &out.dprnt, &out.vars,
                                   &out.log};
  static_assert(std::size(contents) == kRowFileExtensions.size());
  for (std::size_t f = 0; f < std::size(contents); ++f) {
    const char* ext = kRowFileExtensions[f];
    const std::string& content = *contents[f];
    // An output the row did not write is no file, and no earlier batch's.
    if (content.empty()) {
      std::error_code ec;
      fs::remove(base + ext, ec);
      continue;
    }
    if (!writeWhole(base + ext, content)) {
      std::fprintf(stderr, "mbc: error: cannot write '%s%s': %s\n",
                   base.c_str(), ext, std::strerror(errno));
      r.exit = 2;
    }
  }
  return r;
}

} // namespace mbc::driver
