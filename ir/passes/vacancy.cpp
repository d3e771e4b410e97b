// vacancy: finds the values that can never be vacant and drops the `tonum`
// (vacant -> 0) of each: arithmetic, functions and negation never give
// vacant, a constant is vacant only as `vacant`, and a phi is never vacant
// when none of its inputs can be. Loads may read a vacant variable.
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"
#include <mbc/value.h>

namespace mbc::ir {

namespace {

bool neverVacantOp(const Inst& inst) {
  switch (inst.op) {
    case Op::Const:
      return !isVacant(inst.imm);
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor:
    case Op::Neg:
    case Op::ToNum:
    case Op::Fn:
    case Op::RoundAddr:
      return true;
    default:
      return false;
  }
}

// Optimistic for phis (assumed never vacant until an input may be), so that
// a loop of phis over numbers is found never vacant.
std::vector<bool> neverVacant(const Function& f) {
  std::vector<bool> never(f.insts.size(), false);
  for (const Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      const Inst& inst = f.insts[id];
      never[id] =
          neverVacantOp(inst) || (inst.op == Op::Phi && inst.type == Type::Num);
    }
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (const Block& block : f.blocks) {
      for (ValueId id : block.insts) {
        const Inst& inst = f.insts[id];
        if (inst.op != Op::Phi || !never[id]) {
          continue;
        }
        for (ValueId op : inst.ops) {
          if (op >= never.size() || !never[op]) {
            never[id] = false;
            changed = true;
            break;
          }
        }
      }
    }
  }
  return never;
}

} // namespace

void runVacancy(Module& m) {
  for (Function& f : m.functions) {
    std::vector<bool> never = neverVacant(f);
    std::vector<ValueId> repl(f.insts.size(), kNoValue);
    std::vector<bool> dead(f.insts.size(), false);
    for (const Block& block : f.blocks) {
      for (ValueId id : block.insts) {
        const Inst& inst = f.insts[id];
        if (inst.op == Op::ToNum && never[inst.ops[0]]) {
          repl[id] = inst.ops[0];
          dead[id] = true;
        }
      }
    }
    replaceUses(f, repl);
    eraseInsts(f, dead);
  }
}

} // namespace mbc::ir
