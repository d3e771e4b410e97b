// Emission of the transfers by sequence number: the computed GOTO, and the
// resume after an NC block or a call (M98 through mbc.resume, M99 P back
// into this program through the IR's landing); ir/evaluator.cpp's resume
// and jumpToSeq are the reference.
#include "codegen/emitter.h"
#include <mbc/runtime.h>

#include <set>

namespace mbc::codegen::detail {

// Computed GOTO (evaluator switchTo), and the switch of an M99 P landing: a
// number outside 1..99999 or without an N is PS0128, worded by the runtime.
void FunctionEmitter::emitSwitch(const ir::Inst& inst) {
  llvm::Value* target = numOperand(inst, 0);
  switchOnSequence(inst, target, 0);
  bool landing = fn_.insts[inst.ops[0]].op == ir::Op::RetSeq;
  leave(b_.CreateCall(
      abi_.fn(Rt::mbrt_raise_sequence),
      {ctx_, m_.cstring(landing ? "M99 P" : "GOTO "), target, name_}));
}

llvm::BasicBlock* FunctionEmitter::switchOnSequence(const ir::Inst& inst,
                                                    llvm::Value* number,
                                                    std::size_t offset) {
  llvm::Value* n = roundHalfAway(number);
  llvm::Value* inRange = b_.CreateAnd(b_.CreateFCmpOGE(n, constant(1)),
                                      b_.CreateFCmpOLE(n, constant(99999)));
  llvm::Value* seq = b_.CreateSelect(inRange, b_.CreateFPToSI(n, abi_.i32),
                                     llvm::ConstantInt::get(abi_.i32, 0));
  llvm::BasicBlock* missing = newBlock("noseq");
  llvm::SwitchInst* sw =
      b_.CreateSwitch(seq, missing, static_cast<unsigned>(inst.cases.size()));
  std::set<std::int64_t> seen;
  for (std::size_t i = 0; i < inst.cases.size(); ++i) {
    if (i + offset >= inst.targets.size() ||
        !seen.insert(inst.cases[i]).second) {
      continue;
    }
    ir::BlockId target = inst.targets[i + offset];
    sw->addCase(llvm::ConstantInt::get(abi_.i32, inst.cases[i]),
                blocks_[target]);
    incoming_[target].push_back({sw->getParent(), current_});
  }
  b_.SetInsertPoint(missing);
  return missing;
}

// M99 P back into this program: to the IR's landing block (its retseq
// reads the number), or through the resume's own case table (hand-written
// IR; lowering always gives the landing). An empty table can only raise
// PS0128.
void FunctionEmitter::jumpToSeq(const ir::Inst& inst, llvm::Value* seq) {
  if (inst.cases.empty() && inst.targets.size() == 2) {
    b_.CreateStore(seq, retSeqSlot_);
    jump(inst.targets[1]);
    return;
  }
  if (inst.cases.empty()) {
    leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                        {ctx_, m_.cstring("M99 P"), seq, name_}));
    return;
  }
  switchOnSequence(inst, seq, 1);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                      {ctx_, m_.cstring("M99 P"), seq, name_}));
}

// What an NC block or a call asks for next. A call's flow is NEXT, with
// has_seq for M99 P; an NC block's goes to mbc.resume, which makes the M98
// call, finishes the run or prepares this program's return.
void FunctionEmitter::emitResume(const ir::Inst& inst) {
  llvm::Value* flow = values_[inst.ops[0]];
  if (fn_.insts[inst.ops[0]].op == ir::Op::CallMacro) {
    llvm::BasicBlock* plain =
        splitIf(b_.CreateICmpNE(b_.CreateExtractValue(flow, kFlowHasSeq),
                                llvm::ConstantInt::get(abi_.i32, 0)),
                false);
    jumpToSeq(inst, b_.CreateExtractValue(flow, kFlowSeq));
    b_.SetInsertPoint(plain);
    jump(inst.targets[0]);
    return;
  }
  b_.CreateStore(flow, flowSlot_);
  llvm::Value* r = b_.CreateCall(m_.resume, {ctx_, flowSlot_, leave_});
  llvm::BasicBlock* next = newBlock("next");
  llvm::BasicBlock* seq = newBlock("m99p");
  llvm::BasicBlock* ret = newBlock("m99");
  llvm::BasicBlock* other = newBlock("stop");
  llvm::SwitchInst* sw = b_.CreateSwitch(r, other, 3);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, 0), next);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, kResumeSeq), seq);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, kResumeLeave), ret);
  b_.SetInsertPoint(next);
  jump(inst.targets[0]);
  b_.SetInsertPoint(seq);
  jumpToSeq(inst, b_.CreateLoad(abi_.f64, b_.CreateStructGEP(
                                              abi_.flow, flowSlot_, kFlowSeq)));
  b_.SetInsertPoint(ret);
  leave(llvm::ConstantInt::get(abi_.i32, 0));
  b_.SetInsertPoint(other);
  leave(r);
}

} // namespace mbc::codegen::detail
