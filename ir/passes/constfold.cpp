// constfold: operations whose operands are constants become constants,
// computed by the same functions the engines run (mbc/arith.h), so folding
// and execution cannot disagree. An operation whose evaluation alarms is
// never folded: the alarm stays where it happens at run time. Vacant is a
// value here like any other (`#0 EQ 0` is false, `#0 + 1` is 1).
// Comparisons have no constant form in the IR; their known truth only folds
// the branches (condbr, land/lor/lxor) that use them.
#include "ir/cfg.h"
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"
#include <mbc/arith.h>
#include <mbc/limits.h>

#include <bit>
#include <optional>

namespace mbc::ir {

namespace {

bool sameBits(Num a, Num b) {
  return isVacant(a) ? isVacant(b)
                     : std::bit_cast<std::uint64_t>(a) ==
                           std::bit_cast<std::uint64_t>(b);
}

class Folder {
public:
  explicit Folder(Function& f)
      : f_(f), nums_(f.insts.size()), bools_(f.insts.size(), -1),
        repl_(f.insts.size(), kNoValue), dead_(f.insts.size(), false) {}

  void run();

private:
  std::optional<Num> num(ValueId v) const;

  int truth(ValueId v) const { return bools_[resolve(repl_, v)]; }

  void setConst(ValueId id, Num v);
  void fold(ValueId id);
  void foldArith(ValueId id);
  void foldFn(ValueId id);
  void foldPhi(ValueId id);
  void foldLogic(ValueId id);
  void foldTerminator(ValueId id);

  Function& f_;
  std::vector<std::optional<Num>> nums_; // known numbers by value
  std::vector<int> bools_;               // known truth: -1, 0 or 1
  std::vector<ValueId> repl_;
  std::vector<bool> dead_;
};

std::optional<Num> Folder::num(ValueId v) const {
  return nums_[resolve(repl_, v)];
}

// Rewrites the instruction in place, so its uses need no change.
void Folder::setConst(ValueId id, Num v) {
  Inst& inst = f_.insts[id];
  inst.op = isVacant(v) ? Op::Vacant : Op::Const;
  inst.type = opInfo(inst.op).result;
  inst.data = isVacant(v) ? Payload{NoData{}} : Payload{Number{v}};
  inst.ops.clear();
  nums_[id] = v;
}

void Folder::run() {
  Cfg cfg = buildCfg(f_);
  for (BlockId b : cfg.rpo) {
    // Copied: folding a phi inserts a constant into the block.
    std::vector<ValueId> insts = f_.blocks[b].insts;
    for (ValueId id : insts) {
      fold(id);
    }
  }
  replaceUses(f_, repl_);
  eraseInsts(f_, dead_);
}

// Loads, effects and the other terminators are never folded.
void Folder::fold(ValueId id) {
  const Inst& inst = f_.insts[id];
  const Op op = inst.op;
  if (op == Op::Const) {
    nums_[id] = inst.get<Number>().value;
  } else if (op == Op::Vacant) {
    nums_[id] = vacant();
  } else if (op == Op::LdVar) {
    if (inst.get<VarNumber>().number == 0) {
      setConst(id, vacant()); // #0 is always vacant and never alarms
    }
  } else if (op == Op::Fn) {
    foldFn(id);
  } else if (op == Op::Phi) {
    foldPhi(id);
  } else if (op == Op::LogAnd || op == Op::LogOr || op == Op::LogXor) {
    foldLogic(id);
  } else if (op == Op::CondBr || op == Op::Switch) {
    foldTerminator(id);
  } else if (binaryOf(op) || relationOf(op) || op == Op::Neg ||
             op == Op::ToNum) {
    foldArith(id);
  }
}

void Folder::foldArith(ValueId id) {
  const Inst& inst = f_.insts[id];
  const std::optional<BinOp> binary = binaryOf(inst.op);
  const std::optional<RelOp> relation = relationOf(inst.op);
  std::optional<Num> a = num(inst.ops[0]);
  std::optional<Num> b =
      inst.ops.size() > 1 ? num(inst.ops[1]) : std::optional<Num>(0.0);
  if (!a || !b) {
    return;
  }
  if (inst.op == Op::Neg) {
    setConst(id, negate(*a));
  } else if (inst.op == Op::ToNum) {
    setConst(id, numeric(*a));
  } else if (relation) {
    bools_[id] = evalCompare(*relation, *a, *b) ? 1 : 0;
  } else {
    Num out = 0;
    if (evalBinary(*binary, *a, *b, &out) == AlarmId::None) {
      setConst(id, out);
    }
  }
}

// The machine's NAT bit (parameter 6004) is only known at run time: a
// function is folded when both settings give the same result.
void Folder::foldFn(ValueId id) {
  const Inst& inst = f_.insts[id];
  Builtin f = inst.get<BuiltinFn>().fn;
  Num args[2] = {0, 0};
  for (std::size_t i = 0; i < inst.ops.size() && i < 2; ++i) {
    std::optional<Num> v = num(inst.ops[i]);
    if (!v) {
      return;
    }
    args[i] = *v;
  }
  Num plain = 0;
  Num nat = 0;
  if (f == Builtin::Adp ||
      evalBuiltin(f, args, MathParams{false}, &plain) != AlarmId::None ||
      evalBuiltin(f, args, MathParams{true}, &nat) != AlarmId::None ||
      !sameBits(plain, nat)) {
    return;
  }
  setConst(id, plain);
}

// A phi of equal constants becomes one constant after the block's phis.
void Folder::foldPhi(ValueId id) {
  const Inst& inst = f_.insts[id];
  std::optional<Num> value;
  for (ValueId op : inst.ops) {
    if (resolve(repl_, op) == id) {
      continue;
    }
    std::optional<Num> v = num(op);
    if (!v || (value && !sameBits(*v, *value))) {
      return;
    }
    value = v;
  }
  if (!value) {
    return;
  }
  BlockId b = inst.block;
  std::uint32_t line = inst.line;
  ValueId c = newInst(f_, Op::Const, b, line); // invalidates `inst`
  insertAt(f_, b, firstNonPhi(f_, b), c);
  nums_.emplace_back();
  bools_.push_back(-1);
  repl_.push_back(kNoValue);
  dead_.push_back(false);
  setConst(c, *value);
  repl_[id] = c;
  dead_[id] = true;
}

// Both operands known: the truth is known. One known operand that does not
// decide the result: the other operand is the result.
void Folder::foldLogic(ValueId id) {
  const Inst& inst = f_.insts[id];
  int a = truth(inst.ops[0]);
  int b = truth(inst.ops[1]);
  if (a >= 0 && b >= 0) {
    bool r = inst.op == Op::LogAnd  ? (a && b)
             : inst.op == Op::LogOr ? (a || b)
                                    : (a != b);
    bools_[id] = r ? 1 : 0;
    return;
  }
  int neutral = inst.op == Op::LogAnd ? 1 : 0;
  if (a == neutral) {
    repl_[id] = inst.ops[1];
  } else if (b == neutral) {
    repl_[id] = inst.ops[0];
  } else if (a == 1 - neutral || b == 1 - neutral) {
    if (inst.op != Op::LogXor) {
      bools_[id] = 1 - neutral; // false AND x, true OR x
    }
  }
}

// A branch on a known condition jumps; a computed GOTO to a known number
// jumps to its case, and keeps its alarm when there is none.
void Folder::foldTerminator(ValueId id) {
  const Inst& inst = f_.insts[id];
  BlockId b = inst.block;
  if (inst.op == Op::CondBr) {
    int t = truth(inst.ops[0]);
    if (t >= 0) {
      replaceByBr(f_, b, inst.targets[t ? 0 : 1]);
    }
    return;
  }
  std::optional<Num> v = num(inst.ops[0]);
  if (!v) {
    return;
  }
  double n = roundHalfAway(numeric(*v));
  const std::vector<std::int64_t>& numbers = inst.get<SequenceCases>().numbers;
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    if (isSequenceNumber(n) && static_cast<double>(numbers[i]) == n) {
      replaceByBr(f_, b, inst.targets[i]);
      return;
    }
  }
}

} // namespace

void runConstFold(Module& m) {
  for (Function& f : m.functions) {
    Folder(f).run();
  }
}

} // namespace mbc::ir
