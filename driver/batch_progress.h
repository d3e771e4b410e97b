// The progress line of `mbc batch` on a terminal: rows done of all, alarms,
// rate and time left, redrawn in place at most ten times a second. Not
// shown when standard error is not a terminal (a log, CI, a cluster job).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace mbc::driver {

class ProgressLine {
public:
  explicit ProgressLine(std::size_t total);

  void update(std::size_t done, std::size_t alarms);
  /// Prints `text` (a whole line) above the progress line.
  void print(const std::string& text);
  /// Removes the progress line.
  void clear();

private:
  void draw();

  bool shown_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::size_t alarms_ = 0;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDraw_;
};

} // namespace mbc::driver
