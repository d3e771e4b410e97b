// Range analysis: for every value of a function in SSA form, an interval
// that holds every number it can take, reading vacant as 0 (as an index of
// `#[...]` does). Intervals are narrowed by the conditions of `condbr` on
// the blocks those conditions guard, and loops are widened, then narrowed
// again, so that a WHILE counter gets its bounds. Used by mem2ssa to prove
// that an indirection cannot reach the locals it promotes.
#pragma once

#include "ir/ir.h"

#include <limits>
#include <optional>
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

/// What the analysis knows of a function whose locals start in given
/// ranges: one range per value id, and per block whether a run may reach
/// it (false only where a condition that dominates it cannot hold, or all
/// the ways in are such blocks).
struct RangeFacts {
  std::vector<Range> values;
  std::vector<bool> reachable;
};

/// `entry[n-1]`, where given, holds every value #n has when the function
/// starts (vacant read as 0): the loads of #n that nothing may have written
/// before on any path take it.
RangeFacts analyseRanges(const Function& f,
                         const std::vector<std::optional<Range>>& entry);

} // namespace mbc::ir
