#include "motion_table.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace py = pybind11;

namespace mbc::python {

namespace {

constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();

/// The whole-number fields of a row, then f, then the axes' fields.
constexpr const char* kHeaderNames[] = {"motion", "line",  "prog",
                                        "file",   "cycle", "plane"};
constexpr std::size_t kFirstAxisField = std::size(kHeaderNames) + 1;

char lower(char axis) {
  return axis >= 'A' && axis <= 'Z' ? static_cast<char>(axis - 'A' + 'a')
                                    : axis;
}

} // namespace

std::int32_t NameTable::find(const char* name) {
  const char* text = name != nullptr ? name : "";
  if (last_ >= 0 && names_[static_cast<std::size_t>(last_)] == text) {
    return last_;
  }
  const auto [it, added] =
      index_.try_emplace(text, static_cast<std::int32_t>(names_.size()));
  if (added) {
    names_.emplace_back(text);
  }
  last_ = it->second;
  return last_;
}

void MotionTable::append(void* user, const mbrt_motion* m) {
  auto& table = *static_cast<MotionTable*>(user);
  const std::size_t width = table.rowBytes() / sizeof(double);
  table.rows_.resize(table.rows_.size() + width);
  double* row = table.rows_.data() + table.count_ * width;
  ++table.count_;
  const bool arc = m->kind == MBRT_MOTION_CW || m->kind == MBRT_MOTION_CCW;
  const Header header{m->kind,
                      m->line,
                      table.programs_.find(m->program),
                      table.files_.find(m->file),
                      m->cycle,
                      m->plane,
                      m->kind == MBRT_MOTION_RAPID ? kAbsent : m->feed};
  std::memcpy(row, &header, sizeof header);
  double* axis = row + sizeof(Header) / sizeof(double);
  const int count =
      std::min(m->axis_count, static_cast<int>(table.axes_.size()));
  for (int a = 0; a < count; ++a, axis += kPerAxis) {
    axis[0] = m->end[a];
    axis[1] = m->machine[a];
    axis[2] = m->start[a];
    axis[3] = m->programmed[a];
    axis[4] = kAbsent;
    for (int c = 0; arc && c < 2; ++c) {
      if (m->center_axes[c] == table.axes_[a]) {
        axis[4] = m->center[c];
      }
    }
  }
}

/// The row type of a machine with these axes, made once per axis set: a
/// dtype costs more to build than a short run takes.
const py::dtype& MotionTable::rowType(const std::string& axes) {
  // Never freed: Python objects must not be destroyed after the
  // interpreter has ended.
  static auto* made = new std::map<std::string, py::dtype>;
  if (const auto found = made->find(axes); found != made->end()) {
    return found->second;
  }
  py::list names, formats, offsets;
  const auto field = [&](const std::string& name, const char* format,
                         std::size_t offset) {
    names.append(name);
    formats.append(format);
    offsets.append(offset);
  };
  for (std::size_t i = 0; i < std::size(kHeaderNames); ++i) {
    field(kHeaderNames[i], "<i4", i * sizeof(std::int32_t));
  }
  field("f", "<f8", offsetof(Header, f));
  std::size_t offset = sizeof(Header);
  for (const char letter : axes) {
    const std::string axis(1, lower(letter));
    for (const char* prefix : {"", "m", "s", "p", "c"}) {
      field(prefix + axis, "<f8", offset);
      offset += sizeof(double);
    }
  }
  return made
      ->emplace(axes,
                py::dtype(names, formats, offsets,
                          static_cast<py::ssize_t>(rowBytes(axes.size()))))
      .first->second;
}

py::dict MotionTable::lastRow(const py::sequence& motionNames) const {
  const std::size_t width = rowBytes() / sizeof(double);
  const double* row = rows_.data() + (count_ - 1) * width;
  Header header;
  std::memcpy(&header, row, sizeof header);
  py::dict out;
  out["motion"] = motionNames[static_cast<std::size_t>(header.motion)];
  out["line"] = header.line;
  out["prog"] = programs_.names()[static_cast<std::size_t>(header.prog)];
  out["file"] = files_.names()[static_cast<std::size_t>(header.file)];
  out["cycle"] = header.cycle;
  out["plane"] = header.plane;
  out["f"] = header.f;
  // The axes' fields follow the header in the row type's order.
  const py::list names = rowType(axes_).attr("names");
  const double* axis = row + sizeof(Header) / sizeof(double);
  for (std::size_t i = kFirstAxisField; i < names.size(); ++i) {
    out[names[i]] = axis[i - kFirstAxisField];
  }
  return out;
}

py::array MotionTable::take() {
  auto* rows = new std::vector<double>(std::move(rows_));
  const py::capsule owner(
      rows, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const auto count = static_cast<py::ssize_t>(count_);
  rows_.clear();
  count_ = 0;
  return py::array(rowType(axes_), {count},
                   {static_cast<py::ssize_t>(rowBytes())}, rows->data(), owner);
}

} // namespace mbc::python
