// The control-flow graph of one function: successors and predecessors from
// the terminators' targets, reverse post-order and immediate dominators.
// Computed on demand by whoever needs it (verifier, passes); never cached.
#pragma once

#include "ir/ir.h"

#include <cstdint>
#include <vector>

namespace mbc::ir {

inline constexpr BlockId kNoBlock = 0xffffffffU;

struct Cfg {
  /// Distinct successors of each block in the order of the terminator's
  /// targets (condbr: true then false; resume: NEXT then the case table).
  /// An edge counts once however many targets name it, so a switch whose
  /// cases share a block gives one edge, and a phi one input for it.
  std::vector<std::vector<BlockId>> succs;
  /// Distinct predecessors of each block, ascending.
  std::vector<std::vector<BlockId>> preds;
  /// The blocks reachable from b0, in reverse post-order (b0 first).
  std::vector<BlockId> rpo;
  /// Position of each block in rpo; kNoBlock when unreachable.
  std::vector<std::uint32_t> rpoIndex;
  /// Immediate dominator of each block: b0 is its own, unreachable blocks
  /// have kNoBlock.
  std::vector<BlockId> idom;

  bool reachable(BlockId b) const {
    return b < rpoIndex.size() && rpoIndex[b] != kNoBlock;
  }

  /// Whether every path from b0 to `b` passes through `a`. A block dominates
  /// itself; otherwise false when either block is unreachable (dominance
  /// means nothing there: the verifier skips uses in unreachable blocks).
  bool dominates(BlockId a, BlockId b) const;
};

/// The targets of the terminator that ends `b` (its last instruction, when
/// that is a terminator), duplicates and out-of-range targets dropped.
/// `marks`: a scratch vector of f.blocks.size() entries, initially
/// kNoBlock, that may be reused for each block of f once.
std::vector<BlockId> successors(const Function& f, BlockId b,
                                std::vector<BlockId>& marks);

/// Successors, predecessors, RPO and dominators (Cooper, Harvey and
/// Kennedy, "A Simple, Fast Dominance Algorithm"). Any function is accepted,
/// malformed ones included.
Cfg buildCfg(const Function& f);

} // namespace mbc::ir
