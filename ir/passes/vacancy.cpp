// vacancy: finds the phis that can never be vacant, types them num, and
// drops every `tonum` (vacant -> 0) whose operand is then a num. A phi is
// never vacant when none of its inputs can be; values of other operations
// have the type their operation defines (only loads and `vacant` are vnum).
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"

namespace mbc::ir {

namespace {

// Optimistic for phis (assumed never vacant until an input may be), so that
// a loop of phis over numbers is found never vacant.
std::vector<bool> neverVacant(const Function& f) {
  std::vector<bool> never(f.insts.size(), false);
  for (const Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      const Inst& inst = f.insts[id];
      never[id] = inst.type == Type::Num || inst.op == Op::Phi;
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
        Inst& inst = f.insts[id];
        if (inst.op == Op::Phi && never[id]) {
          inst.type = Type::Num;
        } else if (inst.op == Op::ToNum && never[inst.ops[0]]) {
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
