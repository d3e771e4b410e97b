// A lathe's multiple repetitive cycles' part of the context: their
// settings, the shape being read and the shapes read so far.
#pragma once

#include <map>
#include <utility>

#include "context.h"
#include "lathe_shape.h"

namespace mbc::rt {

/// A lathe's shape cycle (G70-G73) reading the blocks ns to nf of its
/// shape program as they run (lathe_shapes.h): they move nothing, their
/// moves make the shape, and the state before them comes back after nf.
struct ShapeReading {
  double ns = 0.0;
  double nf = 0.0;
  bool started = false;        // block ns has run
  bool feedSet = false;        // a block of the shape gave F
  bool firstWordsRead = false; // block ns's axis words have been seen
  bool typeTwo = false;        // block ns wrote the cut axis too (G71 Z, G72 X)
  Shape shape;
  // The cycle's settings: the finishing allowance (G71-G73), G71/G72's
  // depth of cut and escape, G73's relief and divisions, all in counts, x
  // a radius.
  ShapePoint allowance;
  Counts depth = 0;
  Counts escape = 0;
  ShapePoint relief;
  int divisions = 1;
  DryRunState before;    // the state the shape's blocks run over
  BlockPlace cycleBlock; // the block of the cycle
};

/// A lathe's multiple repetitive cycles: their settings, the shape being
/// read and those read so far.
struct LatheState {
  // The parameters of a lathe's multiple repetitive cycles (5130-5143)
  // that a cycle's first block set, until power-off (lengths in mm).
  std::map<int, double> cycleSettings;
  ShapeReading shapeReading;
  // The shapes read so far by (ns, nf), for G70.
  std::map<std::pair<double, double>, Shape> shapes;

  /// Power-on: no settings and no shapes.
  void reset() { *this = LatheState{}; }
};

} // namespace mbc::rt
