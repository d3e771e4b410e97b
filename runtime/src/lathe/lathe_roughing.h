// The geometry of a lathe's shape cycles: a finishing shape as a chain of
// lines and arcs in the ZX plane (counts, X a radius), and the moves that
// G71 (stock removal in turning), G72 (in facing) and G73 (pattern
// repeating) make from it. Pure geometry: lathe_shapes.h runs the moves.
#pragma once

#include <vector>

#include "lathe_shape.h"

namespace mbc::rt {

/// The settings of a roughing cycle: depth of cut Δd and escape e (along
/// X for G71, along Z for G72), finishing allowance (x a radius).
struct Roughing {
  bool facing = false;  // G72: cuts along X, steps in Z
  bool pockets = false; // type II: the shape may dip across the cuts
  double depth = 0.0;
  double escape = 0.0;
  ShapePoint allowance;
};

/// Why a shape cannot be roughed: none, or a shape that is not monotonic
/// across the cuts (type I, PS0064) or along them (type II, PS0064 too).
enum class ShapeFault { None, NotMonotonic };

/// G71/G72 type I: cuts Δd apart from A towards the shape, each from A's
/// level along the cut axis to the shape (less the allowance), escaping e at
/// 45 degrees and returning at rapid; then along the shape shifted by the
/// allowance, and back to A. The cuts start at A's level along the cut
/// axis whatever the first move does: under tool nose radius compensation
/// it is the start-up move, beside the programmed one. The shape must be
/// type I (lathe_shapes.h judges by the words of its first block).
ShapeFault roughShape(const Shape& shape, const Roughing& roughing,
                      std::vector<ShapeMove>& out);

/// Type II in G71's frame (cuts along z), called by roughShape: the shape
/// may dip across the cuts (pockets) but must not turn back along them.
ShapeFault roughPockets(const Shape& shape, const Roughing& roughing,
                        std::vector<ShapeMove>& out);

/// G73: `divisions` passes along the shape shifted by the allowance plus
/// a share of the relief that shrinks to 0, each from A and back to A.
void repeatShape(const Shape& shape, ShapePoint allowance, ShapePoint relief,
                 int divisions, std::vector<ShapeMove>& out);

} // namespace mbc::rt
