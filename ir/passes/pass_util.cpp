// Shared pass helpers (see pass_util.h).
#include "ir/passes/pass_util.h"

#include "ir/cfg.h"
#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/limits.h>

#include <algorithm>

namespace mbc::ir {

bool readCannotAlarm(std::int64_t n) {
  return n == 0 || isLocal(n) || isFixedCommon(n);
}

namespace {

/// A G word that may call: not a constant, or a code that may call.
bool mayCallByG(const Function& f, const Inst& nc, std::size_t i,
                bool modalToo) {
  const Inst& value = f.insts[nc.ops[i]];
  if (value.op == Op::Vacant) {
    return false;
  }
  if (value.op != Op::Const) {
    return true;
  }
  const double tenths = roundHalfAway(value.get<Number>().value * 10.0);
  if (tenths < 0.0 || tenths > 99999.0) {
    return false; // PS0010 at run time
  }
  return gCodeMayCall(static_cast<int>(tenths), modalToo);
}

bool blockMayCallByG(const Function& f, const Inst& nc, bool modalToo) {
  const std::vector<AddressWord>& words = nc.get<Words>().words;
  for (std::size_t i = 0; i < nc.ops.size() && i < words.size(); ++i) {
    if (words[i].letter == 'G' && mayCallByG(f, nc, i, modalToo)) {
      return true;
    }
  }
  return false;
}

} // namespace

bool ncMayShareFrame(const Function& f, const Inst& nc) {
  const std::vector<AddressWord>& words = nc.get<Words>().words;
  for (std::size_t i = 0; i < nc.ops.size() && i < words.size(); ++i) {
    const char letter = words[i].letter;
    const Inst& value = f.insts[nc.ops[i]];
    if (value.op == Op::Vacant) {
      continue; // a vacant word is no word
    }
    if (letterMayCall(letter)) {
      return true;
    }
    // Every M code but those that stop or end may be M98, M99 or a code
    // that calls a subprogram, which shares this frame.
    if (letter == 'M') {
      if (value.op != Op::Const) {
        return true;
      }
      const bool negated = words[i].kind == WordKind::NegVar;
      const double code = value.get<Number>().value;
      if (mCodeMayCall(roundHalfAway(negated ? -code : code))) {
        return true;
      }
    }
  }
  return false;
}

std::int64_t varNumberOf(const Inst& inst) {
  const auto* var = std::get_if<VarNumber>(&inst.data);
  return var != nullptr ? var->number : -1;
}

ValueId terminatorOf(const Function& f, BlockId b) {
  return f.blocks[b].insts.empty() ? kNoValue : f.blocks[b].insts.back();
}

ValueId newInst(Function& f, Op op, BlockId block, std::uint32_t line,
                std::vector<ValueId> ops) {
  Inst inst;
  inst.op = op;
  inst.type = opInfo(op).result;
  inst.block = block;
  inst.line = line;
  inst.ops = std::move(ops);
  inst.data = payloadOf(op);
  f.insts.push_back(std::move(inst));
  return static_cast<ValueId>(f.insts.size() - 1);
}

void insertAt(Function& f, BlockId b, std::size_t pos, ValueId id) {
  std::vector<ValueId>& insts = f.blocks[b].insts;
  insts.insert(insts.begin() + static_cast<std::ptrdiff_t>(pos), id);
  f.insts[id].block = b;
}

std::size_t firstNonPhi(const Function& f, BlockId b) {
  const std::vector<ValueId>& insts = f.blocks[b].insts;
  std::size_t i = 0;
  while (i < insts.size() && f.insts[insts[i]].op == Op::Phi) {
    ++i;
  }
  return i;
}

void clearInst(Function& f, ValueId id) {
  f.insts[id] = Inst{};
}

void eraseInsts(Function& f, const std::vector<bool>& dead) {
  for (Block& block : f.blocks) {
    std::erase_if(block.insts, [&](ValueId id) { return dead[id]; });
  }
  for (ValueId id = 0; id < dead.size(); ++id) {
    if (dead[id]) {
      clearInst(f, id);
    }
  }
}

ValueId resolve(const std::vector<ValueId>& repl, ValueId v) {
  while (v < repl.size() && repl[v] != kNoValue) {
    v = repl[v];
  }
  return v;
}

void replaceUses(Function& f, const std::vector<ValueId>& repl) {
  for (Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      for (ValueId& op : f.insts[id].ops) {
        op = resolve(repl, op);
      }
    }
  }
}

void retarget(Inst& term, BlockId from, BlockId to) {
  std::replace(term.targets.begin(), term.targets.end(), from, to);
}

void dropPhiInputs(Function& f, BlockId b, BlockId pred) {
  for (ValueId id : f.blocks[b].insts) {
    Inst& phi = f.insts[id];
    if (phi.op != Op::Phi) {
      break;
    }
    for (std::size_t i = phi.targets.size(); i-- > 0;) {
      if (phi.targets[i] == pred) {
        phi.targets.erase(phi.targets.begin() + static_cast<std::ptrdiff_t>(i));
        phi.ops.erase(phi.ops.begin() + static_cast<std::ptrdiff_t>(i));
      }
    }
  }
}

void replaceByBr(Function& f, BlockId b, BlockId to) {
  Inst& term = f.insts[terminatorOf(f, b)];
  std::vector<BlockId> old = term.targets;
  std::sort(old.begin(), old.end());
  old.erase(std::unique(old.begin(), old.end()), old.end());
  for (BlockId t : old) {
    if (t != to && t < f.blocks.size()) {
      dropPhiInputs(f, t, b);
    }
  }
  Inst& br = f.insts[terminatorOf(f, b)];
  br.op = Op::Br;
  br.type = Type::None;
  br.ops.clear();
  br.data = NoData{};
  br.targets = {to};
}

BlockId splitEdge(Function& f, BlockId from, BlockId to) {
  auto mid = static_cast<BlockId>(f.blocks.size());
  f.blocks.emplace_back();
  ValueId br = newInst(f, Op::Br, mid, f.insts[terminatorOf(f, from)].line);
  f.insts[br].targets = {to};
  f.blocks[mid].insts.push_back(br);
  retarget(f.insts[terminatorOf(f, from)], to, mid);
  for (ValueId id : f.blocks[to].insts) {
    if (f.insts[id].op != Op::Phi) {
      break;
    }
    retarget(f.insts[id], from, mid);
  }
  return mid;
}

namespace {

// Maps every target of the kept blocks' terminators and phis to the new
// numbers; phi inputs from dropped blocks go.
void renumberTargets(Function& f, const std::vector<BlockId>& newId) {
  for (BlockId b = 0; b < f.blocks.size(); ++b) {
    for (ValueId id : f.blocks[b].insts) {
      Inst& inst = f.insts[id];
      inst.block = b;
      if (inst.op == Op::Phi) {
        for (std::size_t i = inst.targets.size(); i-- > 0;) {
          if (newId[inst.targets[i]] == kNoBlock) {
            auto at = static_cast<std::ptrdiff_t>(i);
            inst.targets.erase(inst.targets.begin() + at);
            inst.ops.erase(inst.ops.begin() + at);
          }
        }
      }
      for (BlockId& t : inst.targets) {
        t = newId[t];
      }
    }
  }
}

} // namespace

bool removeUnreachableBlocks(Function& f) {
  Cfg cfg = buildCfg(f);
  if (cfg.rpo.size() == f.blocks.size()) {
    return false;
  }
  std::vector<BlockId> newId(f.blocks.size(), kNoBlock);
  std::vector<Block> kept;
  for (BlockId b = 0; b < f.blocks.size(); ++b) {
    if (cfg.reachable(b)) {
      newId[b] = static_cast<BlockId>(kept.size());
      kept.push_back(std::move(f.blocks[b]));
    } else {
      for (ValueId id : f.blocks[b].insts) {
        clearInst(f, id);
      }
    }
  }
  f.blocks = std::move(kept);
  renumberTargets(f, newId);
  return true;
}

bool ncMayCall(const Function& f, const Inst& nc) {
  return ncMayShareFrame(f, nc) || blockMayCallByG(f, nc, false);
}

bool moduleMayCallByG(const Module& m) {
  for (const Function& f : m.functions) {
    for (const Inst& inst : f.insts) {
      if (inst.op == Op::Nc && blockMayCallByG(f, inst, true)) {
        return true;
      }
    }
  }
  return false;
}

} // namespace mbc::ir
