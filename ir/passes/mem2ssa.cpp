// mem2ssa: promotes the locals #1..#33 of a function to SSA values with
// phis, where that is provably invisible:
//  - only locals that no indirection (ldind, stind, adp: ADP needs to know
//    how the local was set) can reach. The function is promoted on a copy
//    as if no indirection reached any local; the range analysis of that copy
//    then bounds every indirection's number. If one may reach a promoted
//    local, the promotion starts again without the locals it may reach.
//    (If the first indirection to reach a promoted local came before any
//    other difference, the copy would compute the same number for it, and
//    that number lies in its range: so no such indirection exists.);
//  - memory holds every local whenever other code can see this frame: a
//    local written since the frame was last synchronised is stored back
//    before `ret` and before the resume of an NC block that may be M98
//    (which runs on this frame) or M99 (which returns to a caller that
//    shares it), and every local is loaded again after such a resume. Other
//    NC blocks (motion, M30) and G65 calls (whose callee has a frame of its
//    own) need neither.
// A store back happens only where the local was written on every path since
// the last synchronisation, as in the original program: storing an unwritten
// local would reset its ADP state (runtime adpMask) even with the same
// value. Where paths with and without a write meet, the store moves up to
// the edges that come from the writing paths.
// After each synchronisation a local is loaded where its value is needed:
// it may be an argument or the caller's value (or vacant), never an assumed
// 0. A load of a local cannot alarm, so where it happens is invisible.
#include "ir/passes/mem2ssa.h"

#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"
#include "ir/passes/ranges.h"
#include <mbc/arith.h>

#include <algorithm>

namespace mbc::ir {

namespace mem2ssa {

namespace {

bool isIndirection(Op op) {
  return op == Op::LdInd || op == Op::StInd || op == Op::Adp;
}

// The locals the function loads or stores by number.
Mask accessedLocals(const Function& f) {
  Mask locals = 0;
  for (const Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      const Inst& inst = f.insts[id];
      const std::int64_t n = varNumberOf(inst);
      if (isLocal(n)) {
        locals |= localBit(n);
      }
    }
  }
  return locals;
}

// The locals whose numbers (rounded half away from zero, as #[...] does)
// lie in r.
Mask localsIn(const Range& r) {
  double lo = std::max(r.lo, 0.0);
  double hi = std::min(r.hi, 40.0);
  if (!(lo <= hi)) {
    return 0; // never computed, or entirely outside 0..40
  }
  double first = std::max(roundHalfAway(lo), double{kFirstLocal});
  double last = std::min(roundHalfAway(hi), double{kLastLocal});
  Mask m = 0;
  for (double k = first; k <= last; ++k) {
    m |= localBit(static_cast<std::int64_t>(k));
  }
  return m;
}

// The locals an indirection of `f` may reach, by the ranges of its numbers.
Mask reachedByIndirection(const Function& f) {
  std::vector<Range> ranges;
  Mask reached = 0;
  for (const Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      const Inst& inst = f.insts[id];
      if (!isIndirection(inst.op)) {
        continue;
      }
      if (ranges.empty()) {
        ranges = valueRanges(f);
      }
      reached |= localsIn(ranges[inst.ops[0]]);
    }
  }
  return reached;
}

// Whether the block ends in a resume that may let other code see this
// frame. A G65 call's never does: the callee has a frame of its own.
bool sharesFrame(const Function& f, BlockId b) {
  const Inst& term = f.insts[terminatorOf(f, b)];
  if (term.op != Op::Resume) {
    return false;
  }
  const Inst& flow = f.insts[term.ops[0]];
  return flow.op != Op::CallMacro &&
         (flow.op != Op::Nc || ncMayShareFrame(f, flow));
}

// Moves the phi inputs of `s` from the predecessors in `from` to a new phi
// in `pad`, which then feeds `s`.
void movePhiInputs(Function& f, BlockId s, BlockId pad,
                   const std::vector<bool>& from) {
  for (std::size_t i = 0; i < f.blocks[s].insts.size(); ++i) {
    ValueId id = f.blocks[s].insts[i];
    if (f.insts[id].op != Op::Phi) {
      break;
    }
    ValueId moved = newInst(f, Op::Phi, pad, 0); // invalidates references
    Inst& phi = f.insts[id];
    Inst& into = f.insts[moved];
    into.type = phi.type;
    Inst kept;
    for (std::size_t k = 0; k < phi.targets.size(); ++k) {
      Inst& to = from[phi.targets[k]] ? into : kept;
      to.ops.push_back(phi.ops[k]);
      to.targets.push_back(phi.targets[k]);
    }
    phi.ops = std::move(kept.ops);
    phi.targets = std::move(kept.targets);
    phi.ops.push_back(moved);
    phi.targets.push_back(pad);
    insertAt(f, pad, f.blocks[pad].insts.size() - 1, moved);
  }
}

// A block entered both from resumes that share the frame and from other
// blocks gets a landing pad for the resumes: the pad is where the locals
// are loaded again, so no edge needs a load of its own.
void addLandingPads(Function& f) {
  Cfg cfg = buildCfg(f);
  std::size_t n = f.blocks.size();
  std::vector<bool> shares(n, false);
  std::vector<std::size_t> fromSharing(n, 0);
  for (BlockId b = 0; b < n; ++b) {
    shares[b] = sharesFrame(f, b);
    if (shares[b]) {
      for (BlockId s : cfg.succs[b]) {
        ++fromSharing[s];
      }
    }
  }
  std::vector<BlockId> pad(n, kNoBlock);
  for (BlockId s = 0; s < n; ++s) {
    if (fromSharing[s] == 0 || fromSharing[s] == cfg.preds[s].size()) {
      continue;
    }
    pad[s] = static_cast<BlockId>(f.blocks.size());
    f.blocks.emplace_back();
    ValueId br = newInst(f, Op::Br, pad[s], 0);
    f.insts[br].targets = {s};
    f.blocks[pad[s]].insts.push_back(br);
    movePhiInputs(f, s, pad[s], shares);
  }
  for (BlockId b = 0; b < n; ++b) {
    if (shares[b]) {
      for (BlockId& t : f.insts[terminatorOf(f, b)].targets) {
        t = pad[t] == kNoBlock ? t : pad[t];
      }
    }
  }
}

Plan makePlan(const Function& f, Mask locals) {
  Plan plan;
  plan.locals = locals;
  plan.cfg = buildCfg(f);
  std::size_t n = f.blocks.size();
  plan.sync.assign(n, false);
  plan.storePoint.assign(n, false);
  plan.writes.assign(n, 0);
  plan.stores.assign(n, 0);
  for (BlockId b = 0; b < n; ++b) {
    const std::vector<BlockId>& preds = plan.cfg.preds[b];
    bool sync = b == 0 || !preds.empty();
    for (BlockId p : preds) {
      sync = sync && sharesFrame(f, p);
    }
    plan.sync[b] = sync;
    const Op exit = f.insts[terminatorOf(f, b)].op;
    plan.storePoint[b] =
        exit == Op::Ret || exit == Op::Raise || sharesFrame(f, b);
    for (ValueId id : f.blocks[b].insts) {
      const Inst& inst = f.insts[id];
      const std::int64_t var = varNumberOf(inst);
      if (inst.op == Op::StVar && isLocal(var) && (locals & localBit(var))) {
        plan.writes[b] |= localBit(var);
      }
    }
  }
  return plan;
}

// Stores on an edge go at the end of its source when that has no other
// successor, else on a block of their own. The plan is then made again for
// the new CFG, keeping the stores.
void placeEdgeStores(Function& f, Plan& plan,
                     const std::vector<EdgeStore>& edges) {
  std::vector<Mask> stores = plan.stores;
  for (const EdgeStore& e : edges) {
    if (plan.cfg.succs[e.from].size() == 1) {
      stores[e.from] |= e.locals;
    } else {
      splitEdge(f, e.from, e.to);
      stores.push_back(e.locals);
    }
  }
  plan = makePlan(f, plan.locals);
  plan.stores = std::move(stores);
}

} // namespace

} // namespace mem2ssa

namespace {

// Promotes `locals` in `work`, a copy of the function: false when the plan
// does not fit (then `work` is half rewritten).
bool promoteInto(Function& work, mem2ssa::Mask locals) {
  using namespace mem2ssa;
  removeUnreachableBlocks(work);
  addLandingPads(work);
  Plan plan = makePlan(work, locals);
  std::vector<EdgeStore> edges;
  // A jump back to b0 (hand-written IR) would need a phi at the entry.
  if (!plan.cfg.preds[0].empty() || !planStores(plan, edges)) {
    return false;
  }
  placeEdgeStores(work, plan, edges);
  if (!rename(work, plan)) {
    return false;
  }
  removeTrivialPhis(work);
  return true;
}

// Each round leaves out at least one more local, so there are at most 33.
void promote(Function& f) {
  using namespace mem2ssa;
  Mask accessed = accessedLocals(f);
  Mask excluded = 0;
  while (Mask locals = accessed & ~excluded) {
    Function work = f;
    if (!promoteInto(work, locals)) {
      return;
    }
    Mask reached = reachedByIndirection(work);
    if ((reached & locals) == 0) {
      f = std::move(work);
      return;
    }
    excluded |= reached;
  }
}

} // namespace

void runMem2Ssa(Module& m) {
  for (Function& f : m.functions) {
    promote(f);
  }
}

} // namespace mbc::ir
