// `mbc run --html`: the toolpath as one page that a browser opens from
// disk: an interactive 3D view (three.js, inside the page) with rapids,
// feeds and arcs by colour, a slider and a play button that show the cut
// move by move, and the source line of the move under the pointer.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mbc::runner {

class HtmlWriter {
public:
  /// Records one move; returns the bytes the page grew by.
  std::size_t add(const mbrt_motion& motion);

  /// The most bytes add() may return for `motion`, whatever was added
  /// before: a writer thread counts it ahead of the page (toolpath_thread.h).
  static std::size_t growthBound(const mbrt_motion& motion);

  /// The whole page under a title, with the text of the source lines the
  /// moves came from (read from their files).
  std::string document(const std::string& title) const;

private:
  int indexOf(std::vector<std::string>& names, const char* name);
  void segmentTo(const std::array<double, 3>& from,
                 const std::array<double, 3>& to);
  void addProgrammed(const mbrt_motion& m);

  std::vector<float> points_; // x, y, z of both ends of each segment
  std::vector<std::uint32_t> segmentMove_;
  std::vector<int> kinds_, files_, lines_, programs_; // per move
  // Each move's end as the control shows it (a lathe's X a diameter).
  std::vector<float> ends_;
  std::vector<std::string> fileNames_, programNames_;
  // The programmed contour where cutter compensation moves the tool off it:
  // segments as points_, drawn beside the tool centre's path.
  std::vector<float> programmed_;
  bool compensated_ = false;
  std::optional<std::array<double, 3>> programmedPen_; // its last point
  bool lathe_ = false;
};

} // namespace mbc::runner
