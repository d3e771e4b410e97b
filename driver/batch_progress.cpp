// See batch_progress.h.
#include "driver/batch_progress.h"

#include <fmt/format.h>

#include <cstdio>
#include <unistd.h>

namespace mbc::driver {

namespace {

constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

std::string minutesSeconds(double seconds) {
  const auto s = static_cast<long long>(seconds + 0.5);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

} // namespace

ProgressLine::ProgressLine(std::size_t total)
    : shown_(isatty(STDERR_FILENO) != 0), total_(total),
      start_(std::chrono::steady_clock::now()), lastDraw_(start_) {
}

void ProgressLine::update(std::size_t done, std::size_t alarms) {
  done_ = done;
  alarms_ = alarms;
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && (now - lastDraw_ >= kRedrawInterval || done == total_)) {
    lastDraw_ = now;
    draw();
  }
}

void ProgressLine::print(const std::string& text) {
  clear();
  std::fprintf(stderr, "%s\n", text.c_str());
  if (shown_) {
    draw();
  }
}

void ProgressLine::clear() {
  if (drawn_) {
    std::fputs("\r\033[K", stderr);
    drawn_ = false;
  }
}

void ProgressLine::draw() {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_)
          .count();
  const double fraction =
      total_ == 0 ? 1.0
                  : static_cast<double>(done_) / static_cast<double>(total_);
  const int filled = static_cast<int>(fraction * kBarWidth);
  const double rate = seconds > 0 ? static_cast<double>(done_) / seconds : 0;
  std::string left = "";
  if (rate > 0 && done_ < total_) {
    left = ", " + minutesSeconds(static_cast<double>(total_ - done_) / rate) +
           " left";
  }
  std::fprintf(stderr,
               "\r\033[K[%s%s] %zu/%zu rows, %zu alarm%s, %.0f rows/s%s",
               std::string(filled, '#').c_str(),
               std::string(kBarWidth - filled, '.').c_str(), done_, total_,
               alarms_, alarms_ == 1 ? "" : "s", rate, left.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

} // namespace mbc::driver
