// loadelim: within a block, a load of a common variable (#100-#999) whose
// value is already known takes that value: the value of an earlier load of
// the same number, or of the last store to it. Knowledge ends where another
// program may run or variables change in ways not seen here: NC blocks
// (M98, and G65 through call.macro) and indirect stores. A second load of
// a number that did not alarm the first time cannot alarm either, so the
// alarm behaviour stays.
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"

#include <unordered_map>

namespace mbc::ir {

namespace {

bool isCommon(std::int64_t n) {
  return n >= 100 && n <= 999;
}

void forwardInBlock(Function& f, const Block& block, std::vector<ValueId>& repl,
                    std::vector<bool>& dead) {
  std::unordered_map<std::int64_t, ValueId> known;
  for (ValueId id : block.insts) {
    const Inst& inst = f.insts[id];
    switch (inst.op) {
      case Op::LdVar:
        if (isCommon(inst.attr)) {
          auto [it, fresh] = known.emplace(inst.attr, id);
          if (!fresh) {
            repl[id] = it->second;
            dead[id] = true;
          }
        }
        break;
      case Op::StVar:
        if (isCommon(inst.attr)) {
          known[inst.attr] = inst.ops[0];
        }
        break;
      default:
        if (opInfo(inst.op).flags & WritesVars) {
          known.clear(); // stind, nc, call.macro, resume
        }
        break;
    }
  }
}

} // namespace

void runLoadElim(Module& m) {
  for (Function& f : m.functions) {
    std::vector<ValueId> repl(f.insts.size(), kNoValue);
    std::vector<bool> dead(f.insts.size(), false);
    for (const Block& block : f.blocks) {
      forwardInBlock(f, block, repl, dead);
    }
    replaceUses(f, repl);
    eraseInsts(f, dead);
  }
}

} // namespace mbc::ir
