// Internals of mem2ssa (mem2ssa.cpp: which locals, where memory must be
// right; mem2ssa_rename.cpp: the SSA values). Not part of the library's
// interface.
#pragma once

#include "ir/cfg.h"
#include "ir/ir.h"
#include <mbc/limits.h>

#include <cstdint>
#include <vector>

namespace mbc::ir::mem2ssa {

/// A set of locals: bit k-1 stands for #k (#1..#33).
using Mask = std::uint64_t;

inline Mask localBit(std::int64_t k) {
  return Mask{1} << (k - 1);
}

struct Plan {
  Mask locals = 0; // the promoted locals
  Cfg cfg;
  /// Memory holds every local at the block's entry (b0, and the blocks
  /// entered only from a resume that may run an M98 subprogram on this
  /// frame): the values are loaded there.
  std::vector<bool> sync;
  /// The block ends where other code sees this frame: ret, or a resume of
  /// an NC block (M98 runs on this frame, M99 returns to a caller that
  /// shares it).
  std::vector<bool> storePoint;
  std::vector<Mask> writes; // locals stored in the block
  /// Locals stored back before the block's terminator.
  std::vector<Mask> stores;
};

/// Locals to store on the edge from -> to.
struct EdgeStore {
  BlockId from;
  BlockId to;
  Mask locals;
};

/// Decides the stores back: Plan::stores of the store points and the stores
/// on edges into joins (sorted by edge, for a deterministic output). False
/// when it cannot (the function then stays in memory form).
bool planStores(Plan& plan, std::vector<EdgeStore>& edges);

/// Rewrites the promoted loads and stores of `f` into SSA values, phis,
/// loads at the sync blocks and the planned stores. False if the plan does
/// not fit the function (then `f` is half rewritten: work on a copy).
bool rename(Function& f, const Plan& plan);

/// Backward may-analysis up to the sync blocks (which load their own
/// locals): the locals in gen[b] at block b, or needed after it without
/// being written in it, at each block's entry.
std::vector<Mask> backwardToSync(const Plan& plan,
                                 const std::vector<Mask>& gen);

} // namespace mbc::ir::mem2ssa
