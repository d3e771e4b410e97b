// loadelim: a load of a common variable (#100-#999), or of a local the
// function keeps in memory, whose value is already known takes that value:
// the value of an earlier load of the same number, or of the last store to
// it, on every path to the load. Knowledge ends where another program may
// run or variables change in ways not seen here: NC blocks (M98, a custom
// macro), calls, resumes and indirect stores. A value known on every path
// is defined on every path, so it dominates the load. A second load of a
// number that did not alarm the first time cannot alarm either, so the
// alarm behaviour stays.
#include "ir/cfg.h"
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"
#include <mbc/limits.h>

#include <map>
#include <optional>

namespace mbc::ir {

namespace {

bool isMemoryVariable(std::int64_t n) {
  return isLocal(n) || (n >= kFirstCommon && n <= kLastNonvolatile);
}

using Known = std::map<std::int64_t, ValueId>;

class LoadElim {
public:
  explicit LoadElim(Function& f)
      : f_(f), repl_(f.insts.size(), kNoValue), dead_(f.insts.size(), false) {}

  void run();

private:
  Known entry(BlockId b) const;
  Known transfer(BlockId b, Known known, bool rewrite);

  Function& f_;
  Cfg cfg_;
  std::vector<std::optional<Known>> out_; // none: not reached yet
  std::vector<ValueId> repl_;
  std::vector<bool> dead_;
};

// What every predecessor knows with the same value; predecessors not
// reached yet do not count (they are met again when the solver repeats).
Known LoadElim::entry(BlockId b) const {
  if (b == 0) {
    return {}; // the caller's frame and the commons: nothing known
  }
  std::optional<Known> in;
  for (BlockId p : cfg_.preds[b]) {
    if (!out_[p]) {
      continue;
    }
    if (!in) {
      in = *out_[p];
      continue;
    }
    for (auto it = in->begin(); it != in->end();) {
      auto other = out_[p]->find(it->first);
      it = other != out_[p]->end() && other->second == it->second
               ? std::next(it)
               : in->erase(it);
    }
  }
  return in.value_or(Known{});
}

Known LoadElim::transfer(BlockId b, Known known, bool rewrite) {
  for (ValueId id : f_.blocks[b].insts) {
    const Inst& inst = f_.insts[id];
    const std::int64_t n = varNumberOf(inst);
    if (inst.op == Op::LdVar && isMemoryVariable(n)) {
      auto [it, fresh] = known.emplace(n, id);
      if (!fresh && rewrite) {
        repl_[id] = it->second;
        dead_[id] = true;
      }
    } else if (inst.op == Op::StVar && isMemoryVariable(n)) {
      known[n] = inst.ops[0];
    } else if (opInfo(inst.op).flags & WritesVars) {
      known.clear(); // stind, nc, call.macro, resume
    }
  }
  return known;
}

void LoadElim::run() {
  cfg_ = buildCfg(f_);
  out_.assign(f_.blocks.size(), std::nullopt);
  for (bool changed = true; changed;) {
    changed = false;
    for (BlockId b : cfg_.rpo) {
      Known out = transfer(b, entry(b), false);
      if (out_[b] != out) {
        out_[b] = std::move(out);
        changed = true;
      }
    }
  }
  for (BlockId b : cfg_.rpo) {
    transfer(b, entry(b), true);
  }
  replaceUses(f_, repl_);
  eraseInsts(f_, dead_);
}

} // namespace

void runLoadElim(Module& m) {
  for (Function& f : m.functions) {
    LoadElim(f).run();
  }
}

} // namespace mbc::ir
