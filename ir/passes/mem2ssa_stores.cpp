// mem2ssa: where the promoted locals are stored back (see mem2ssa.cpp). A
// local is "dirty" once written since the frame was last synchronised (b0,
// or a sync block after a resume). Every store point stores its dirty
// locals. A store is exact only where the local is dirty on every path, so
// where dirty and clean paths meet and the difference still matters, the
// edges from dirty predecessors store first (and are clean after). Stores
// go on edges, not at the end of the predecessor, to keep them out of loops
// that exit to such a join.
#include "ir/passes/mem2ssa.h"

#include <algorithm>
#include <unordered_map>

namespace mbc::ir::mem2ssa {

std::vector<Mask> backwardToSync(const Plan& plan,
                                 const std::vector<Mask>& gen) {
  std::vector<Mask> in(gen.size(), 0);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = plan.cfg.rpo.size(); i-- > 0;) {
      BlockId b = plan.cfg.rpo[i];
      Mask out = 0;
      for (BlockId s : plan.cfg.succs[b]) {
        out |= plan.sync[s] ? 0 : in[s];
      }
      Mask v = gen[b] | (out & ~plan.writes[b]);
      if (v != in[b]) {
        in[b] = v;
        changed = true;
      }
    }
  }
  return in;
}

namespace {

// Backward: the locals whose dirtiness at a block's entry matters, because
// a path from there reaches a store point before writing them.
std::vector<Mask> demandAtEntry(const Plan& plan) {
  std::vector<Mask> gen(plan.sync.size(), 0);
  for (BlockId b = 0; b < gen.size(); ++b) {
    gen[b] = plan.storePoint[b] ? plan.locals : 0;
  }
  return backwardToSync(plan, gen);
}

struct Dirty {
  std::vector<Mask> mayIn, mustIn, mayOut, mustOut;
};

/// The locals stored on each edge so far, by from << 32 | to.
using EdgeMasks = std::unordered_map<std::uint64_t, Mask>;

std::uint64_t edgeKey(BlockId from, BlockId to) {
  return static_cast<std::uint64_t>(from) << 32 | to;
}

Mask storedOn(const EdgeMasks& fixed, BlockId from, BlockId to) {
  auto it = fixed.find(edgeKey(from, to));
  return it == fixed.end() ? 0 : it->second;
}

// Forward: the locals dirty on some (may) or every (must) path, with the
// stores already placed on edges (`fixed`).
void computeDirty(const Plan& plan, const EdgeMasks& fixed, Dirty& d) {
  std::size_t n = plan.sync.size();
  d.mayIn.assign(n, 0);
  d.mustIn.assign(n, 0);
  d.mayOut.assign(n, 0);
  d.mustOut.assign(n, plan.locals); // optimistic until a path says otherwise
  for (bool changed = true; changed;) {
    changed = false;
    for (BlockId b : plan.cfg.rpo) {
      Mask may = 0;
      Mask must = plan.sync[b] ? 0 : plan.locals;
      if (!plan.sync[b]) {
        for (BlockId p : plan.cfg.preds[b]) {
          Mask stored = storedOn(fixed, p, b);
          may |= d.mayOut[p] & ~stored;
          must &= d.mustOut[p] & ~stored;
        }
      }
      d.mayIn[b] = may;
      d.mustIn[b] = must;
      Mask mayOut = may | plan.writes[b];
      Mask mustOut = must | plan.writes[b];
      if (mayOut != d.mayOut[b] || mustOut != d.mustOut[b]) {
        d.mayOut[b] = mayOut;
        d.mustOut[b] = mustOut;
        changed = true;
      }
    }
  }
}

// Stores on the edges from predecessors that are dirty on every path into
// a block where dirty and clean paths meet. True if any was added.
bool fixMixedJoins(const Plan& plan, const std::vector<Mask>& demand,
                   const Dirty& d, EdgeMasks& fixed) {
  bool added = false;
  for (BlockId b : plan.cfg.rpo) {
    Mask mixed = d.mayIn[b] & ~d.mustIn[b] & demand[b];
    if (plan.sync[b] || mixed == 0) {
      continue;
    }
    for (BlockId p : plan.cfg.preds[b]) {
      Mask add = mixed & d.mustOut[p] & ~storedOn(fixed, p, b);
      if (add != 0) {
        fixed[edgeKey(p, b)] |= add;
        added = true;
      }
    }
  }
  return added;
}

} // namespace

bool planStores(Plan& plan, std::vector<EdgeStore>& edges) {
  std::vector<Mask> demand = demandAtEntry(plan);
  EdgeMasks fixed;
  Dirty d;
  do {
    computeDirty(plan, fixed, d);
  } while (fixMixedJoins(plan, demand, d, fixed));
  for (BlockId b : plan.cfg.rpo) {
    if (!plan.storePoint[b]) {
      continue;
    }
    if ((d.mayIn[b] & ~d.mustIn[b] & ~plan.writes[b]) != 0) {
      return false; // cannot happen after fixMixedJoins; never guess
    }
    plan.stores[b] = d.mayIn[b] | plan.writes[b];
  }
  edges.clear();
  for (auto [key, locals] : fixed) {
    edges.push_back({static_cast<BlockId>(key >> 32),
                     static_cast<BlockId>(key & 0xffffffffU), locals});
  }
  std::sort(edges.begin(), edges.end(),
            [](const EdgeStore& a, const EdgeStore& b) {
              return a.from != b.from ? a.from < b.from : a.to < b.to;
            });
  return true;
}

} // namespace mbc::ir::mem2ssa
