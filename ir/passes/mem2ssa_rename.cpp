// mem2ssa: the SSA values of the promoted locals (see mem2ssa.cpp). Phis go
// at every join where a local is live (simpler than dominance frontiers;
// mem2ssa then removes those that one definition reaches by every path); a
// sync block loads its live locals from memory. Blocks are visited in reverse
// post-order, so a block with one predecessor takes that predecessor's values
// at its end.
#include "ir/passes/mem2ssa.h"
#include "ir/passes/pass_util.h"

#include <array>

namespace mbc::ir::mem2ssa {

namespace {

using Values = std::array<ValueId, kLocalCount>; // current value of #1..#33

Values noValues() {
  Values v;
  v.fill(kNoValue);
  return v;
}

Mask liveGen(const Function& f, const Plan& plan, BlockId b) {
  Mask written = 0;
  Mask gen = 0;
  for (ValueId id : f.blocks[b].insts) {
    const Inst& inst = f.insts[id];
    const std::int64_t n = varNumberOf(inst);
    if (!isLocal(n) || !(plan.locals & localBit(n))) {
      continue;
    }
    if (inst.op == Op::LdVar && !(written & localBit(n))) {
      gen |= localBit(n);
    } else if (inst.op == Op::StVar) {
      written |= localBit(n);
    }
  }
  return gen | (plan.stores[b] & ~written); // a store back reads the value
}

// Backward: the locals whose value is needed at each block's entry. A sync
// block loads its own, so liveness does not flow past it.
std::vector<Mask> liveAtEntry(const Function& f, const Plan& plan) {
  std::size_t n = f.blocks.size();
  std::vector<Mask> gen(n, 0);
  for (BlockId b = 0; b < n; ++b) {
    gen[b] = liveGen(f, plan, b);
  }
  return backwardToSync(plan, gen);
}

class Renamer {
public:
  Renamer(Function& f, const Plan& plan)
      : f_(f), plan_(plan), exit_(f.blocks.size(), noValues()),
        repl_(f.insts.size(), kNoValue), dead_(f.insts.size(), false) {}

  bool run();

private:
  void enter(BlockId b, Values& cur);
  bool rewriteBlock(BlockId b, Values& cur);
  bool storeBack(BlockId b, const Values& cur);
  bool fillPhis();

  Function& f_;
  const Plan& plan_;
  std::vector<Mask> live_;
  std::vector<Values> exit_; // values at each block's end
  std::vector<ValueId> repl_;
  std::vector<bool> dead_;
  std::vector<std::pair<ValueId, int>> phis_; // new phi, local index
};

bool Renamer::run() {
  live_ = liveAtEntry(f_, plan_);
  for (BlockId b : plan_.cfg.rpo) {
    Values cur;
    enter(b, cur);
    if (!rewriteBlock(b, cur) || !storeBack(b, cur)) {
      return false;
    }
    exit_[b] = cur;
  }
  if (!fillPhis()) {
    return false;
  }
  dead_.resize(f_.insts.size(), false);
  replaceUses(f_, repl_);
  eraseInsts(f_, dead_);
  return true;
}

// The values at the entry: loads in a sync block, phis at a join, else the
// single predecessor's values.
void Renamer::enter(BlockId b, Values& cur) {
  const std::vector<BlockId>& preds = plan_.cfg.preds[b];
  if (!plan_.sync[b] && preds.size() == 1) {
    cur = exit_[preds[0]];
    return;
  }
  cur = noValues();
  std::size_t pos = firstNonPhi(f_, b);
  for (int k = 0; k < kLocalCount; ++k) {
    if (!(live_[b] & (Mask{1} << k))) {
      continue;
    }
    ValueId v = newInst(f_, plan_.sync[b] ? Op::LdVar : Op::Phi, b, 0);
    if (plan_.sync[b]) {
      f_.insts[v].get<VarNumber>().number = k + 1;
    }
    insertAt(f_, b, pos++, v);
    if (!plan_.sync[b]) {
      phis_.emplace_back(v, k);
    }
    cur[k] = v;
  }
}

bool Renamer::rewriteBlock(BlockId b, Values& cur) {
  for (ValueId id : f_.blocks[b].insts) {
    const Inst& inst = f_.insts[id];
    const std::int64_t n = varNumberOf(inst);
    if (!isLocal(n) || !(plan_.locals & localBit(n))) {
      continue;
    }
    if (repl_.size() <= id) {
      continue; // a load this pass added
    }
    auto k = static_cast<std::size_t>(n - 1);
    if (inst.op == Op::StVar) {
      cur[k] = inst.ops[0];
    } else if (cur[k] == kNoValue) {
      return false; // liveness missed a read: leave the function alone
    } else {
      repl_[id] = cur[k];
    }
    dead_[id] = true;
  }
  return true;
}

bool Renamer::storeBack(BlockId b, const Values& cur) {
  ValueId term = terminatorOf(f_, b);
  std::uint32_t line = f_.insts[term].line;
  for (int k = 0; k < kLocalCount; ++k) {
    if (!(plan_.stores[b] & (Mask{1} << k))) {
      continue;
    }
    if (cur[k] == kNoValue) {
      return false;
    }
    ValueId st = newInst(f_, Op::StVar, b, line, {cur[k]});
    f_.insts[st].get<VarNumber>().number = k + 1;
    insertAt(f_, b, f_.blocks[b].insts.size() - 1, st);
  }
  return true;
}

bool Renamer::fillPhis() {
  for (auto [phi, k] : phis_) {
    BlockId b = f_.insts[phi].block;
    for (BlockId p : plan_.cfg.preds[b]) {
      ValueId v = exit_[p][static_cast<std::size_t>(k)];
      if (v == kNoValue) {
        return false;
      }
      f_.insts[phi].ops.push_back(v);
      f_.insts[phi].targets.push_back(p);
    }
  }
  return true;
}

} // namespace

bool rename(Function& f, const Plan& plan) {
  return Renamer(f, plan).run();
}

} // namespace mbc::ir::mem2ssa
