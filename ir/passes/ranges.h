// Range analysis: for every value of a function in SSA form, an interval
// that holds every number it can take, reading vacant as 0 (as an index of
// `#[...]` does). Intervals are narrowed by the conditions of `condbr` on
// the blocks those conditions guard, and loops are widened, then narrowed
// again, so that a WHILE counter gets its bounds. Used by mem2ssa to prove
// that an indirection cannot reach the locals it promotes.
#pragma once

#include "ir/ir.h"

#include <limits>
#include <vector>

namespace mbc::ir {

struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();

  bool operator==(const Range&) const = default;
};

/// One range per value id (every number for values that are not numbers,
/// and for values the analysis gave up on).
std::vector<Range> valueRanges(const Function& f);

} // namespace mbc::ir
