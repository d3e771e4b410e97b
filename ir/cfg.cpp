// CFG, reverse post-order and dominators (see cfg.h). Iterative everywhere:
// a long program is one long chain of blocks, deeper than the C++ stack.
#include "ir/cfg.h"

#include <utility>

namespace mbc::ir {

namespace {

void computeRpo(Cfg& cfg) {
  std::size_t n = cfg.succs.size();
  cfg.rpoIndex.assign(n, kNoBlock);
  if (n == 0) {
    return;
  }
  // Depth-first search with an explicit stack of (block, next successor).
  std::vector<bool> seen(n, false);
  std::vector<std::pair<BlockId, std::size_t>> stack{{0, 0}};
  std::vector<BlockId> post;
  seen[0] = true;
  while (!stack.empty()) {
    auto& [b, next] = stack.back();
    if (next < cfg.succs[b].size()) {
      BlockId s = cfg.succs[b][next++];
      if (!seen[s]) {
        seen[s] = true;
        stack.emplace_back(s, 0);
      }
      continue;
    }
    post.push_back(b);
    stack.pop_back();
  }
  cfg.rpo.assign(post.rbegin(), post.rend());
  for (std::size_t i = 0; i < cfg.rpo.size(); ++i) {
    cfg.rpoIndex[cfg.rpo[i]] = static_cast<std::uint32_t>(i);
  }
}

BlockId intersect(const Cfg& cfg, BlockId a, BlockId b) {
  while (a != b) {
    while (cfg.rpoIndex[a] > cfg.rpoIndex[b]) {
      a = cfg.idom[a];
    }
    while (cfg.rpoIndex[b] > cfg.rpoIndex[a]) {
      b = cfg.idom[b];
    }
  }
  return a;
}

void computeDominators(Cfg& cfg) {
  cfg.idom.assign(cfg.succs.size(), kNoBlock);
  if (cfg.rpo.empty()) {
    return;
  }
  cfg.idom[0] = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 1; i < cfg.rpo.size(); ++i) {
      BlockId b = cfg.rpo[i];
      BlockId idom = kNoBlock;
      for (BlockId p : cfg.preds[b]) {
        if (cfg.idom[p] != kNoBlock) {
          idom = idom == kNoBlock ? p : intersect(cfg, p, idom);
        }
      }
      if (cfg.idom[b] != idom) {
        cfg.idom[b] = idom;
        changed = true;
      }
    }
  }
}

} // namespace

// marks[t] == b once t is in b's list: a resume names every sequence
// number's block, so a linear search for duplicates would be quadratic.
std::vector<BlockId> successors(const Function& f, BlockId b,
                                std::vector<BlockId>& marks) {
  std::vector<BlockId> out;
  if (b >= f.blocks.size() || f.blocks[b].insts.empty()) {
    return out;
  }
  ValueId last = f.blocks[b].insts.back();
  if (last >= f.insts.size() ||
      !(opInfo(f.insts[last].op).flags & Terminator)) {
    return out;
  }
  for (BlockId t : f.insts[last].targets) {
    if (t < f.blocks.size() && marks[t] != b) {
      marks[t] = b;
      out.push_back(t);
    }
  }
  return out;
}

bool Cfg::dominates(BlockId a, BlockId b) const {
  if (a == b) {
    return true;
  }
  if (!reachable(a) || !reachable(b)) {
    return false;
  }
  // Dominators sit earlier in RPO, so climb until we pass a's position.
  while (rpoIndex[b] > rpoIndex[a]) {
    b = idom[b];
  }
  return a == b;
}

Cfg buildCfg(const Function& f) {
  Cfg cfg;
  std::size_t n = f.blocks.size();
  cfg.succs.resize(n);
  cfg.preds.resize(n);
  std::vector<BlockId> marks(n, kNoBlock);
  for (BlockId b = 0; b < n; ++b) {
    cfg.succs[b] = successors(f, b, marks);
    for (BlockId s : cfg.succs[b]) {
      cfg.preds[s].push_back(b); // b ascends, so preds come out sorted
    }
  }
  computeRpo(cfg);
  computeDominators(cfg);
  return cfg;
}

} // namespace mbc::ir
