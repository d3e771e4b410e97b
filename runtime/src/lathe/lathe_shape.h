// A lathe's finishing shape as its shape cycles (G70-G73) read it: a
// chain of lines and arcs in the ZX plane, counts, X a radius.
#pragma once

#include <string>
#include <vector>

namespace mbc::rt {

/// A point of the ZX plane: x a radius, counts.
struct ShapePoint {
  double x = 0.0;
  double z = 0.0;
};

enum class ShapeMotion { Rapid, Line, Clockwise, CounterClockwise };

/// One move of a shape (or of a cycle's path): to `end` from the previous
/// one's end, about `center` for arcs. `feed`: the F the shape program set
/// for it, 0 when it set none (the cycle's F applies). `compensation`: the
/// G40, G41 or G42 in force for it (a path already compensated has G40).
/// `line`: the line of the shape's block that made it, 0 for a move of the
/// cycle's own.
struct ShapeMove {
  ShapeMotion motion = ShapeMotion::Line;
  ShapePoint end;
  ShapePoint center;
  double feed = 0.0;
  int compensation = 40;
  int line = 0;
};

/// A finishing shape: the start point A of its cycle and the moves of the
/// blocks ns to nf, the first of them from A to the shape's start A'.
struct Shape {
  ShapePoint start;
  std::vector<ShapeMove> moves;
  std::string file; // of the blocks ns to nf
};

} // namespace mbc::rt
