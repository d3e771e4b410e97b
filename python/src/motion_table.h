// The motions of a run as rows of a numpy structured array: a motion sink
// writes each motion once, straight into the row memory the array then
// takes over (no copy per motion, none when the array is made).
#pragma once

#include <mbc/runtime.h>

#include <cstddef>
#include <cstdint>
#include <pybind11/numpy.h>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mbc::python {

/// Program or file names numbered by first appearance, which the rows'
/// `prog` and `file` columns hold. A machine keeps one pair for all its
/// runs, so that the rows of all its runs number names alike (their arrays
/// concatenate).
class NameTable {
public:
  std::int32_t find(const char* name);

  const std::vector<std::string>& names() const { return names_; }

private:
  std::vector<std::string> names_;
  std::unordered_map<std::string, std::int32_t> index_;
  // Most motions come from the block before's program and file: their text
  // is compared first, before any hashing.
  std::int32_t last_ = -1;
};

class MotionTable {
public:
  /// For a machine with these axes ("XYZ"), in profile order, numbering
  /// names in the tables given (which must outlive it).
  MotionTable(std::string axes, NameTable& programs, NameTable& files)
      : axes_(std::move(axes)), programs_(programs), files_(files) {}

  /// The motion sink: `user` is the table.
  static void append(void* user, const mbrt_motion* motion);

  std::size_t size() const { return count_; }

  /// Room for this many rows (a machine's last run is a good guess).
  void reserve(std::size_t rows) {
    rows_.reserve(rows * rowBytes() / sizeof(double));
  }

  /// The names the rows' `prog` and `file` columns index.
  const std::vector<std::string>& programs() const { return programs_.names(); }

  const std::vector<std::string>& files() const { return files_.names(); }

  /// The rows as a numpy array that owns their memory; the table is left
  /// empty. Fields: motion (0 rapid, 1 linear, 2 cw, 3 ccw), line, prog,
  /// file, cycle (81 for G81, 0), plane, f (NaN for rapids), then per axis
  /// in profile order, for X: x (end, workpiece), mx (machine), sx (start),
  /// px (programmed end) and cx (arc centre, NaN off the arc plane).
  pybind11::array take();

  /// The last row as a dict of its fields, for a callback: `motion`
  /// named by `motionNames`, `prog` and `file` by their names.
  pybind11::dict lastRow(const pybind11::sequence& motionNames) const;

  /// The row type of a machine with these axes.
  static const pybind11::dtype& rowType(const std::string& axes);

private:
  struct Header {
    std::int32_t motion, line, prog, file, cycle, plane;
    double f;
  };

  static constexpr int kPerAxis = 5; // end, machine, start, programmed, centre

  static std::size_t rowBytes(std::size_t axisCount) {
    return sizeof(Header) + sizeof(double) * kPerAxis * axisCount;
  }

  std::size_t rowBytes() const { return rowBytes(axes_.size()); }

  std::string axes_;
  std::vector<double> rows_; // whole rows of doubles (the header is 4 doubles)
  std::size_t count_ = 0;
  NameTable& programs_;
  NameTable& files_;
};

} // namespace mbc::python
