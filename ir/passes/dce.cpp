// dce: removes the blocks b0 does not reach, then every instruction whose
// value nothing live uses and whose execution nothing can observe. Live are
// terminators and instructions with effects: side effects, variable writes
// and alarms (an alarm stops the run at its block, so `1/0` stays even when
// unused). A read of a variable that always exists cannot alarm, so an
// unused `ldvar #1` goes while `ldvar #50` (PS0115) stays.
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"

namespace mbc::ir {

namespace {

bool mustKeep(const Inst& inst) {
  unsigned flags = opInfo(inst.op).flags;
  if (flags & (Terminator | SideEffect | WritesVars)) {
    return true;
  }
  if (inst.op == Op::LdVar) {
    return !readCannotAlarm(inst.get<VarNumber>().number);
  }
  return (flags & MayAlarm) != 0;
}

// Marks from the instructions that must stay through their operands, so
// that dead cycles of phis go too.
void removeDeadInsts(Function& f) {
  std::vector<bool> live(f.insts.size(), false);
  std::vector<ValueId> work;
  for (const Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      if (mustKeep(f.insts[id])) {
        live[id] = true;
        work.push_back(id);
      }
    }
  }
  while (!work.empty()) {
    ValueId id = work.back();
    work.pop_back();
    for (ValueId op : f.insts[id].ops) {
      if (op < live.size() && !live[op]) {
        live[op] = true;
        work.push_back(op);
      }
    }
  }
  std::vector<bool> dead(f.insts.size(), false);
  for (const Block& block : f.blocks) {
    for (ValueId id : block.insts) {
      dead[id] = !live[id];
    }
  }
  eraseInsts(f, dead);
}

} // namespace

void runDce(Module& m) {
  for (Function& f : m.functions) {
    removeUnreachableBlocks(f);
    removeDeadInsts(f);
  }
}

} // namespace mbc::ir
