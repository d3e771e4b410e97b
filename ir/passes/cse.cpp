// cse: an instruction that computes what a dominating one already computed
// (same operation, attribute and operands; constants compared by value,
// commutative operands in either order) takes that value and goes. Only
// operations whose result depends on nothing but their operands qualify:
// arithmetic and functions too, because when the first computation did not
// alarm, the same computation on the same values cannot alarm either.
// Loads (loadelim's job), phis, block-skip and address rounding (machine
// state) and effects stay.
#include "ir/cfg.h"
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"

#include <algorithm>
#include <bit>
#include <map>

namespace mbc::ir {

namespace {

bool isCandidate(Op op) {
  return (opInfo(op).flags & Cseable) != 0;
}

bool isCommutative(Op op) {
  return (opInfo(op).flags & Commutative) != 0;
}

using Key = std::vector<std::uint64_t>;

class Cse {
public:
  explicit Cse(Function& f)
      : f_(f), repl_(f.insts.size(), kNoValue), dead_(f.insts.size(), false) {}

  void run();

private:
  Key keyOf(const Inst& inst) const;
  std::vector<Key> number(BlockId b);

  Function& f_;
  Cfg cfg_;
  std::map<Key, ValueId> available_;
  std::vector<ValueId> repl_;
  std::vector<bool> dead_;
};

// A constant operand is keyed by its value, so that two `const 1` match.
Key Cse::keyOf(const Inst& inst) const {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> ops;
  for (ValueId op : inst.ops) {
    const Inst& def = f_.insts[resolve(repl_, op)];
    if (def.op == Op::Const) {
      ops.emplace_back(1,
                       std::bit_cast<std::uint64_t>(def.get<Number>().value));
    } else {
      ops.emplace_back(0, resolve(repl_, op));
    }
  }
  if (isCommutative(inst.op)) {
    std::sort(ops.begin(), ops.end());
  }
  // Of the Cseable ops only fn has a payload (ir_opcodes_test checks).
  const auto* fn = std::get_if<BuiltinFn>(&inst.data);
  Key key{static_cast<std::uint64_t>(inst.op),
          fn != nullptr ? static_cast<std::uint64_t>(fn->fn) : 0};
  for (const auto& [tag, value] : ops) {
    key.push_back(tag);
    key.push_back(value);
  }
  return key;
}

// Depth-first over the dominator tree: what a block computes is available
// in the blocks it dominates and forgotten when the walk leaves it. An
// explicit stack, because a long program is a dominator chain of thousands
// of blocks.
void Cse::run() {
  cfg_ = buildCfg(f_);
  std::vector<std::vector<BlockId>> children(f_.blocks.size());
  for (BlockId b : cfg_.rpo) {
    if (b != 0) {
      children[cfg_.idom[b]].push_back(b);
    }
  }

  struct Visit {
    BlockId block;
    std::size_t next = 0; // next child to visit
    std::vector<Key> added;
  };

  std::vector<Visit> stack;
  if (!cfg_.rpo.empty()) {
    stack.push_back(Visit{0, 0, number(0)});
  }
  while (!stack.empty()) {
    Visit& top = stack.back();
    if (top.next < children[top.block].size()) {
      BlockId child = children[top.block][top.next++];
      stack.push_back(Visit{child, 0, number(child)});
      continue;
    }
    for (const Key& key : top.added) {
      available_.erase(key);
    }
    stack.pop_back();
  }
  replaceUses(f_, repl_);
  eraseInsts(f_, dead_);
}

// Replaces each candidate of `b` that is already available; returns the
// keys `b` made available.
std::vector<Key> Cse::number(BlockId b) {
  std::vector<Key> added;
  for (ValueId id : f_.blocks[b].insts) {
    const Inst& inst = f_.insts[id];
    if (!isCandidate(inst.op)) {
      continue;
    }
    Key key = keyOf(inst);
    auto [it, fresh] = available_.emplace(key, id);
    if (fresh) {
      added.push_back(std::move(key));
    } else {
      repl_[id] = it->second;
      dead_[id] = true;
    }
  }
  return added;
}

} // namespace

void runCse(Module& m) {
  for (Function& f : m.functions) {
    Cse(f).run();
  }
}

} // namespace mbc::ir
