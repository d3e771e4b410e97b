// removeTrivialPhis (see pass_util.h): the phi cleanup of copyprop and
// mem2ssa. A phi that stands for one value, alone or together with other
// phis that only pass values around among themselves (a redundant SCC, as
// in Braun et al. 2013, "Simple and Efficient Construction of Static Single
// Assignment Form", section 3.2), is that value. Both kinds arise where
// locals are promoted across the case tables of computed GOTOs and resumes.
#include "ir/passes/pass_util.h"

#include <algorithm>

namespace mbc::ir {

namespace {

// The single value a phi stands for, or kNoValue when its inputs differ
// (or are all the phi itself: then it only exists in dead code).
ValueId trivialValue(const Function& f, const std::vector<ValueId>& repl,
                     ValueId phi) {
  ValueId unique = kNoValue;
  for (ValueId op : f.insts[phi].ops) {
    ValueId v = resolve(repl, op);
    if (v == phi || v == unique) {
      continue;
    }
    if (unique != kNoValue) {
      return kNoValue;
    }
    unique = v;
  }
  return unique;
}

bool isLivePhi(const Function& f, const std::vector<bool>& dead, ValueId v) {
  return v < f.insts.size() && f.insts[v].op == Op::Phi && !dead[v] &&
         f.insts[v].block < f.blocks.size();
}

bool removeSinglePhis(const Function& f, std::vector<ValueId>& repl,
                      std::vector<bool>& dead) {
  bool any = false;
  for (bool changed = true; changed;) {
    changed = false;
    for (const Block& block : f.blocks) {
      for (ValueId id : block.insts) {
        if (f.insts[id].op != Op::Phi) {
          break;
        }
        ValueId v = dead[id] ? kNoValue : trivialValue(f, repl, id);
        if (v != kNoValue) {
          repl[id] = v;
          dead[id] = true;
          changed = any = true;
        }
      }
    }
  }
  return any;
}

// Tarjan's strongly connected components of the graph of live phis (an edge
// from a phi to each phi input), iteratively: phi chains can be long.
class PhiSccs {
public:
  PhiSccs(const Function& f, const std::vector<ValueId>& repl,
          const std::vector<bool>& dead)
      : f_(f), repl_(repl), dead_(dead), index_(f.insts.size(), kUnseen),
        low_(f.insts.size(), 0), onStack_(f.insts.size(), false) {}

  /// Calls `each` with every component (a list of phis).
  template <typename Each> void run(Each each) {
    for (const Block& block : f_.blocks) {
      for (ValueId id : block.insts) {
        if (f_.insts[id].op != Op::Phi) {
          break;
        }
        if (!dead_[id] && index_[id] == kUnseen) {
          visit(id, each);
        }
      }
    }
  }

private:
  static constexpr std::uint32_t kUnseen = 0xffffffffU;

  template <typename Each> void visit(ValueId root, Each& each) {
    std::vector<std::pair<ValueId, std::size_t>> work{{root, 0}};
    open(root);
    while (!work.empty()) {
      auto& [v, next] = work.back();
      const std::vector<ValueId>& ops = f_.insts[v].ops;
      if (next < ops.size()) {
        ValueId w = resolve(repl_, ops[next++]);
        if (!isLivePhi(f_, dead_, w)) {
          continue;
        }
        if (index_[w] == kUnseen) {
          open(w);
          work.emplace_back(w, 0);
        } else if (onStack_[w]) {
          low_[v] = std::min(low_[v], index_[w]);
        }
        continue;
      }
      ValueId done = v;
      work.pop_back();
      if (!work.empty()) {
        low_[work.back().first] = std::min(low_[work.back().first], low_[done]);
      }
      if (low_[done] == index_[done]) {
        each(close(done));
      }
    }
  }

  void open(ValueId v) {
    index_[v] = low_[v] = counter_++;
    stack_.push_back(v);
    onStack_[v] = true;
  }

  std::vector<ValueId> close(ValueId root) {
    std::vector<ValueId> scc;
    ValueId w = kNoValue;
    do {
      w = stack_.back();
      stack_.pop_back();
      onStack_[w] = false;
      scc.push_back(w);
    } while (w != root);
    return scc;
  }

  const Function& f_;
  const std::vector<ValueId>& repl_;
  const std::vector<bool>& dead_;
  std::vector<std::uint32_t> index_, low_;
  std::vector<bool> onStack_;
  std::vector<ValueId> stack_;
  std::uint32_t counter_ = 0;
};

// A group of phis whose inputs from outside the group are all one value
// is that value.
bool removeRedundantSccs(const Function& f, std::vector<ValueId>& repl,
                         std::vector<bool>& dead) {
  std::vector<std::pair<std::vector<ValueId>, ValueId>> found;
  std::vector<bool> inScc(f.insts.size(), false);
  PhiSccs(f, repl, dead).run([&](const std::vector<ValueId>& scc) {
    for (ValueId p : scc) {
      inScc[p] = true;
    }
    ValueId outside = kNoValue;
    bool single = scc.size() > 1;
    for (ValueId p : scc) {
      for (ValueId op : f.insts[p].ops) {
        ValueId v = resolve(repl, op);
        if (inScc[v] || v == outside) {
          continue;
        }
        single = single && outside == kNoValue;
        outside = v;
      }
    }
    for (ValueId p : scc) {
      inScc[p] = false;
    }
    if (single && outside != kNoValue) {
      found.emplace_back(scc, outside);
    }
  });
  for (const auto& [scc, value] : found) {
    for (ValueId p : scc) {
      repl[p] = value;
      dead[p] = true;
    }
  }
  return !found.empty();
}

} // namespace

bool removeTrivialPhis(Function& f) {
  std::vector<ValueId> repl(f.insts.size(), kNoValue);
  std::vector<bool> dead(f.insts.size(), false);
  bool any = false;
  for (;;) {
    // Both run every round: each can expose work for the other.
    const bool single = removeSinglePhis(f, repl, dead);
    const bool sccs = removeRedundantSccs(f, repl, dead);
    if (!single && !sccs) {
      break;
    }
    any = true;
  }
  if (any) {
    replaceUses(f, repl);
    eraseInsts(f, dead);
  }
  return any;
}

} // namespace mbc::ir
