#include "runner/html_writer.h"

#include <mbc/number_text.h>
#include <mbc/read_file.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "runner/arc_geometry.h"
#include "runner/html_page.h"
#include "runner/xml_text.h"

namespace mbc::runner {

namespace {

enum MoveKind { kRapid = 0, kFeed = 1, kArc = 2 };

// Segments of an arc: about one per 7.5 degrees, at least 4.
constexpr double kSegmentsPerTurn = 48.0;

/// How many segments draw an arc (the tool's, or the programmed one).
int arcPieces(const Arc& arc) {
  return std::max(4, static_cast<int>(std::ceil(std::fabs(arc.sweep) /
                                                (2.0 * std::numbers::pi) *
                                                kSegmentsPerTurn)));
}

// What the page counts against the output limit: about 8 bytes of it per
// coordinate, 40 per move.
constexpr std::size_t kBytesPerCoordinate = 8;
constexpr std::size_t kBytesPerMove = 40;

std::array<double, 3> xyz(const double* point, const mbrt_motion& m) {
  std::array<double, 3> out{};
  const char letters[] = {'X', 'Y', 'Z'};
  for (int i = 0; i < 3; ++i) {
    const int axis = axisNamed(m, letters[i]);
    out[static_cast<std::size_t>(i)] = axis >= 0 ? point[axis] : 0.0;
  }
  return out;
}

template <typename T> std::string joined(const std::vector<T>& values) {
  std::string out;
  for (const T& v : values) {
    out += out.empty() ? "" : ",";
    if constexpr (std::is_floating_point_v<T>) {
      out += trimmedFixed(static_cast<double>(v), 4);
    } else {
      out += std::to_string(v);
    }
  }
  return out;
}

std::string jsonString(const std::string& text) {
  return nlohmann::json(text).dump(-1, ' ', false,
                                   nlohmann::json::error_handler_t::replace);
}

} // namespace

int HtmlWriter::indexOf(std::vector<std::string>& names, const char* name) {
  const std::string text = name != nullptr ? name : "";
  // Moves come in runs from one file and program: the last one first.
  if (!names.empty() && names.back() == text) {
    return static_cast<int>(names.size()) - 1;
  }
  const auto it = std::find(names.begin(), names.end(), text);
  if (it != names.end()) {
    return static_cast<int>(it - names.begin());
  }
  names.push_back(text);
  return static_cast<int>(names.size()) - 1;
}

void HtmlWriter::segmentTo(const std::array<double, 3>& from,
                           const std::array<double, 3>& to) {
  for (const auto& point : {from, to}) {
    for (const double v : point) {
      points_.push_back(static_cast<float>(v));
    }
  }
  segmentMove_.push_back(static_cast<std::uint32_t>(kinds_.size() - 1));
}

/// The programmed contour of a move, where compensation runs the tool
/// beside it: from the last programmed point to this one, an arc with the
/// tool arc's centre and turn (the tool's offset arc is concentric), a
/// rapid lifting the pen.
void HtmlWriter::addProgrammed(const mbrt_motion& m) {
  const std::array<double, 3> to = xyz(m.programmed, m);
  const std::array<double, 3> end = xyz(m.end, m);
  compensated_ = compensated_ || to != end;
  const std::array<double, 3> from = programmedPen_.value_or(xyz(m.start, m));
  programmedPen_ = to;
  if (m.kind == MBRT_MOTION_RAPID || from == to) {
    return;
  }
  const auto segment = [&](const std::array<double, 3>& a,
                           const std::array<double, 3>& b) {
    for (const auto& point : {a, b}) {
      for (const double v : point) {
        programmed_.push_back(static_cast<float>(v));
      }
    }
  };
  if (m.kind != MBRT_MOTION_CW && m.kind != MBRT_MOTION_CCW) {
    segment(from, to);
    return;
  }
  // The tool arc's points moved along their radii onto the programmed one.
  const Arc a = arcOf(m);
  const double scale = a.radius > 0.0
                           ? std::hypot(m.programmed[a.p] - m.center[0],
                                        m.programmed[a.q] - m.center[1]) /
                                 a.radius
                           : 1.0;
  const int pieces = arcPieces(a);
  std::array<double, 3> last = from;
  for (int i = 1; i <= pieces; ++i) {
    auto point = arcPoint(m, a, static_cast<double>(i) / pieces);
    point[a.p] = m.center[0] + (point[a.p] - m.center[0]) * scale;
    point[a.q] = m.center[1] + (point[a.q] - m.center[1]) * scale;
    const std::array<double, 3> next = i == pieces ? to : xyz(point.data(), m);
    segment(last, next);
    last = next;
  }
}

std::size_t HtmlWriter::add(const mbrt_motion& motion) {
  const mbrt_motion m = motion.diameter_mask != 0 ? inRadii(motion) : motion;
  const std::size_t before = points_.size() + programmed_.size();
  lathe_ = isLatheMotion(m);
  for (const double v : xyz(motion.end, motion)) {
    ends_.push_back(static_cast<float>(v));
  }
  addProgrammed(m);
  const bool arc = m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW;
  kinds_.push_back(m.kind == MBRT_MOTION_RAPID ? kRapid : arc ? kArc : kFeed);
  files_.push_back(indexOf(fileNames_, m.file));
  lines_.push_back(m.line);
  programs_.push_back(indexOf(programNames_, m.program));
  std::array<double, 3> from = xyz(m.start, m);
  if (arc) {
    const Arc a = arcOf(m);
    const int pieces = arcPieces(a);
    for (int i = 1; i <= pieces; ++i) {
      const auto point = arcPoint(m, a, static_cast<double>(i) / pieces);
      const std::array<double, 3> to = xyz(point.data(), m);
      segmentTo(from, to);
      from = to;
    }
  } else {
    segmentTo(from, xyz(m.end, m));
  }
  return (points_.size() + programmed_.size() - before) * kBytesPerCoordinate +
         kBytesPerMove;
}

std::size_t HtmlWriter::growthBound(const mbrt_motion& motion) {
  const mbrt_motion m = motion.diameter_mask != 0 ? inRadii(motion) : motion;
  const bool arc = m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW;
  const auto pieces = static_cast<std::size_t>(arc ? arcPieces(arcOf(m)) : 1);
  // The tool's segments and as many of the programmed contour, each two
  // points of three coordinates.
  return 2 * pieces * 6 * kBytesPerCoordinate + kBytesPerMove;
}

std::string HtmlWriter::document(const std::string& title) const {
  // The text of every source line a move came from.
  std::set<std::pair<int, int>> wanted;
  for (std::size_t i = 0; i < kinds_.size(); ++i) {
    wanted.insert({files_[i], lines_[i]});
  }
  std::string source;
  int readFileIndex = -1;
  std::vector<std::string> fileLines;
  for (const auto& [file, line] : wanted) {
    if (file != readFileIndex) {
      readFileIndex = file;
      fileLines.clear();
      std::string text;
      if (readFile(fileNames_[static_cast<std::size_t>(file)], text) == 0) {
        for (std::size_t at = 0; at <= text.size();) {
          const std::size_t end = std::min(text.find('\n', at), text.size());
          std::string one = text.substr(at, end - at);
          if (!one.empty() && one.back() == '\r') {
            one.pop_back();
          }
          fileLines.push_back(one.substr(0, 200));
          at = end + 1;
        }
      }
    }
    if (line >= 1 && static_cast<std::size_t>(line) <= fileLines.size()) {
      source += fmt::format(
          "{}\"{}:{}\":{}", source.empty() ? "" : ",", file, line,
          jsonString(fileLines[static_cast<std::size_t>(line - 1)]));
    }
  }
  std::string names, programs;
  for (const std::string& f : fileNames_) {
    names += (names.empty() ? "" : ",") + jsonString(f);
  }
  for (const std::string& p : programNames_) {
    programs += (programs.empty() ? "" : ",") + jsonString(p);
  }
  std::string data = fmt::format(
      "{{\"title\":{},\"lathe\":{},\"files\":[{}],\"programs\":[{}],"
      "\"source\":{{{}}},"
      "\"moves\":{{\"kind\":[{}],\"file\":[{}],\"line\":[{}],\"program\":[{}],"
      "\"end\":[{}]}},"
      "\"points\":[{}],\"segmentMove\":[{}],\"programmed\":[{}]}}",
      jsonString(title), lathe_, names, programs, source, joined(kinds_),
      joined(files_), joined(lines_), joined(programs_), joined(ends_),
      joined(points_), joined(segmentMove_),
      compensated_ ? joined(programmed_) : "");
  // No "</script>" inside the script element: JSON may write "<\/".
  for (std::size_t at = data.find("</"); at != std::string::npos;
       at = data.find("</", at + 3)) {
    data.insert(at + 1, "\\");
  }
  std::string page(toolpathPage());
  page.replace(page.find("@TOOLPATH@"), 10, data);
  page.replace(page.find("@TITLE@"), 7, xmlEscaped(title));
  return page;
}

} // namespace mbc::runner
