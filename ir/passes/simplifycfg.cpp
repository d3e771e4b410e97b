// simplifycfg: merges a block into its predecessor when that predecessor
// jumps only to it and it has no other predecessor, and lets jumps go past
// blocks that hold nothing but a `br`. Neither changes what runs: every
// `begin` stays, in order, so blocks are counted and alarms located as
// before. b0 keeps no predecessor. The landing of a resume whose NC block
// cannot call a program goes: no M99 P can come back at an N there.
#include "ir/cfg.h"
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"

namespace mbc::ir {

namespace {

// condbr to one block twice is a br.
void simplifyBranches(Function& f) {
  for (BlockId b = 0; b < f.blocks.size(); ++b) {
    const Inst& term = f.insts[terminatorOf(f, b)];
    if (term.op == Op::CondBr && term.targets[0] == term.targets[1]) {
      replaceByBr(f, b, term.targets[0]);
    }
  }
}

void pruneResumeCases(Function& f, bool gCodesMayCall) {
  for (BlockId b = 0; b < f.blocks.size(); ++b) {
    Inst& term = f.insts[terminatorOf(f, b)];
    if (term.op != Op::Resume || term.targets.size() < 2) {
      continue;
    }
    const Inst& flow = f.insts[term.ops[0]];
    if (flow.op != Op::Nc || gCodesMayCall || ncMayCall(f, flow)) {
      continue;
    }
    std::vector<BlockId> dropped(term.targets.begin() + 1, term.targets.end());
    term.targets.resize(1);
    term.data = SequenceCases{};
    for (BlockId t : dropped) {
      if (t != term.targets[0]) {
        dropPhiInputs(f, t, b);
      }
    }
  }
}

BlockId root(const std::vector<BlockId>& into, BlockId b) {
  while (into[b] != kNoBlock) {
    b = into[b];
  }
  return b;
}

// One sweep in reverse post-order merges whole chains: when b joins its
// predecessor p, b's terminator now ends the block p went into.
void mergeChains(Function& f) {
  Cfg cfg = buildCfg(f);
  std::vector<BlockId> into(f.blocks.size(), kNoBlock);
  std::vector<ValueId> repl(f.insts.size(), kNoValue);
  for (BlockId b : cfg.rpo) {
    if (b == 0 || cfg.preds[b].size() != 1 || cfg.preds[b][0] == b) {
      continue;
    }
    BlockId r = root(into, cfg.preds[b][0]);
    ValueId term = terminatorOf(f, r);
    if (f.insts[term].op != Op::Br || f.insts[term].targets[0] != b) {
      continue;
    }
    f.blocks[r].insts.pop_back();
    clearInst(f, term);
    for (ValueId id : f.blocks[b].insts) {
      if (f.insts[id].op == Op::Phi) {
        repl[id] = f.insts[id].ops[0]; // the only predecessor's value
        clearInst(f, id);
      } else {
        f.blocks[r].insts.push_back(id);
        f.insts[id].block = r;
      }
    }
    f.blocks[b].insts.clear();
    into[b] = r;
  }
  for (Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      if (f.insts[id].op == Op::Phi) {
        for (BlockId& t : f.insts[id].targets) {
          t = root(into, t);
        }
      }
    }
  }
  replaceUses(f, repl);
}

bool isEmptyJump(const Function& f, BlockId b) {
  const std::vector<ValueId>& insts = f.blocks[b].insts;
  return b != 0 && insts.size() == 1 && f.insts[insts[0]].op == Op::Br &&
         f.insts[insts[0]].targets[0] != b;
}

// The input of phi `phi` for predecessor `pred`, or kNoValue.
ValueId phiInput(const Inst& phi, BlockId pred) {
  for (std::size_t i = 0; i < phi.targets.size(); ++i) {
    if (phi.targets[i] == pred) {
      return phi.ops[i];
    }
  }
  return kNoValue;
}

// Whether every predecessor of e can jump to t directly: one that already
// does must agree with e on every phi input of t.
bool canThread(const Function& f, const Cfg& cfg, BlockId e, BlockId t) {
  for (BlockId p : cfg.preds[e]) {
    for (ValueId id : f.blocks[t].insts) {
      const Inst& phi = f.insts[id];
      if (phi.op != Op::Phi) {
        break;
      }
      ValueId direct = phiInput(phi, p);
      if (direct != kNoValue && direct != phiInput(phi, e)) {
        return false;
      }
    }
  }
  return true;
}

void thread(Function& f, const Cfg& cfg, BlockId e, BlockId t) {
  for (ValueId id : f.blocks[t].insts) {
    Inst& phi = f.insts[id];
    if (phi.op != Op::Phi) {
      break;
    }
    ValueId v = phiInput(phi, e);
    for (BlockId p : cfg.preds[e]) {
      if (phiInput(phi, p) == kNoValue) {
        phi.ops.push_back(v);
        phi.targets.push_back(p);
      }
    }
  }
  dropPhiInputs(f, t, e);
  for (BlockId p : cfg.preds[e]) {
    retarget(f.insts[terminatorOf(f, p)], e, t);
  }
}

// Rounds until nothing changes; a block whose edges changed waits for the
// next round, since the CFG of this one no longer describes it.
void threadJumps(Function& f) {
  for (bool changed = true; changed;) {
    changed = false;
    Cfg cfg = buildCfg(f);
    std::vector<bool> touched(f.blocks.size(), false);
    for (BlockId e = 1; e < f.blocks.size(); ++e) {
      if (!cfg.reachable(e) || !isEmptyJump(f, e)) {
        continue;
      }
      BlockId t = f.insts[f.blocks[e].insts[0]].targets[0];
      bool busy = touched[e] || touched[t];
      for (BlockId p : cfg.preds[e]) {
        busy = busy || touched[p];
      }
      if (busy || !canThread(f, cfg, e, t)) {
        continue;
      }
      thread(f, cfg, e, t);
      touched[e] = touched[t] = true;
      for (BlockId p : cfg.preds[e]) {
        touched[p] = true;
      }
      changed = true;
    }
    removeUnreachableBlocks(f);
  }
}

} // namespace

void runSimplifyCfg(Module& m) {
  const bool gCodesMayCall = moduleMayCallByG(m);
  for (Function& f : m.functions) {
    simplifyBranches(f);
    pruneResumeCases(f, gCodesMayCall);
    mergeChains(f);
    removeUnreachableBlocks(f);
    threadJumps(f);
  }
}

} // namespace mbc::ir
