// Emission of the transfers by sequence number: the computed GOTO, and the
// resume after an NC block or a call (M98 through mbc.resume, M99 P back
// into this program through the IR's landing); ir/evaluator.cpp's resume
// and jumpToSeq are the reference.
#include "codegen/emitter.h"
#include <mbc/engine.h>
#include <mbc/limits.h>

#include <set>

namespace mbc::codegen::detail {

// Computed GOTO (evaluator switchTo), and the switch of an M99 P landing: a
// number outside 1..99999 or without an N is PS0128, worded by the runtime.
// The start of a program an M98 Q entered (evaluator startAt) is
// PS0078 when it has no such N.
void FunctionEmitter::emitSwitch(const ir::Inst& inst) {
  llvm::Value* target = numOperand(inst, 0);
  switchOnSequence(inst, target);
  const ir::Op from = fn_.insts[inst.ops[0]].op;
  if (from == ir::Op::StartSeq) {
    leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_start_sequence),
                        {ctx_, target, name_}));
    return;
  }
  bool landing = from == ir::Op::RetSeq;
  leave(b_.CreateCall(
      abi_.fn(Rt::mbrt_raise_sequence),
      {ctx_, m_.cstring(landing ? "M99 P" : "GOTO "), target, name_}));
}

llvm::BasicBlock* FunctionEmitter::switchOnSequence(const ir::Inst& inst,
                                                    llvm::Value* number) {
  const std::vector<std::int64_t>& numbers =
      inst.get<ir::SequenceCases>().numbers;
  const std::size_t offset = ir::firstCaseTarget(inst.op);
  llvm::Value* n = roundHalfAway(number);
  llvm::Value* inRange =
      b_.CreateAnd(b_.CreateFCmpOGE(n, constant(1)),
                   b_.CreateFCmpOLE(n, constant(kMaxSequenceNumber)));
  llvm::Value* seq = b_.CreateSelect(inRange, b_.CreateFPToSI(n, abi_.i32),
                                     llvm::ConstantInt::get(abi_.i32, 0));
  llvm::BasicBlock* missing = newBlock("noseq");
  llvm::SwitchInst* sw =
      b_.CreateSwitch(seq, missing, static_cast<unsigned>(numbers.size()));
  std::set<std::int64_t> seen;
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    if (i + offset >= inst.targets.size() || !seen.insert(numbers[i]).second) {
      continue;
    }
    ir::BlockId target = inst.targets[i + offset];
    sw->addCase(llvm::ConstantInt::get(abi_.i32, numbers[i]), blocks_[target]);
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
  const ir::SequenceCases& cases = inst.get<ir::SequenceCases>();
  if (cases.landing) {
    b_.CreateStore(seq, retSeqSlot_);
    jump(inst.targets[1]);
    return;
  }
  if (cases.numbers.empty()) {
    leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                        {ctx_, m_.cstring("M99 P"), seq, name_}));
    return;
  }
  switchOnSequence(inst, seq);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                      {ctx_, m_.cstring("M99 P"), seq, name_}));
}

// What an NC block or a call asks for next. A call's flow is NEXT, with
// has_seq for M99 P; an NC block's goes to mbc.resume, which makes the M98
// call, finishes the run or prepares this program's return. Only NEXT has
// an edge of its own: M99 P and leaving go to blocks the function's
// resumes share, so that an NC block costs LLVM no blocks of its own.
void FunctionEmitter::emitResume(const ir::Inst& inst) {
  llvm::Value* flow = values_[inst.ops[0]];
  llvm::BasicBlock* here = b_.GetInsertBlock();
  ir::BlockId next = inst.targets[0];
  if (fn_.insts[inst.ops[0]].op == ir::Op::CallMacro) {
    b_.CreateCondBr(b_.CreateICmpNE(b_.CreateExtractValue(flow, kFlowHasSeq),
                                    llvm::ConstantInt::get(abi_.i32, 0)),
                    seqBlock(inst), blocks_[next]);
    incoming_[next].push_back({here, current_});
    return;
  }
  storeFlow(flow);
  llvm::Value* r = b_.CreateCall(m_.resume, {ctx_, flowSlot_, leave_});
  llvm::BasicBlock* left = leftBlock();
  resumeStatus_->add(b_, r);
  llvm::SwitchInst* sw = b_.CreateSwitch(r, left, 2);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, 0), blocks_[next]);
  incoming_[next].push_back({here, current_});
  sw->addCase(llvm::ConstantInt::get(abi_.i32, kResumeSeq), seqBlock(inst));
}

// The flow an NC block gave is still in its slot unless something wrote
// memory since it was read.
void FunctionEmitter::storeFlow(llvm::Value* flow) {
  auto* load = llvm::dyn_cast<llvm::LoadInst>(flow);
  bool fresh = load != nullptr && load->getPointerOperand() == flowSlot_ &&
               load->getParent() == b_.GetInsertBlock();
  for (llvm::Instruction* i = load; fresh && i != nullptr;
       i = i->getNextNode()) {
    fresh = !i->mayWriteToMemory();
  }
  if (!fresh) {
    b_.CreateStore(flow, flowSlot_);
  } else if (load->use_empty()) {
    load->eraseFromParent();
  }
}

// Where a callee's M99 P comes back: the landing (or the PS0128 that
// stands for an empty table) is the same for every resume of the function
// and gets one block; a resume with its own case table gets its own.
llvm::BasicBlock* FunctionEmitter::seqBlock(const ir::Inst& inst) {
  const ir::SequenceCases& cases = inst.get<ir::SequenceCases>();
  bool toLanding = cases.landing;
  bool shared =
      cases.numbers.empty() && (!toLanding || !blockHasPhis(inst.targets[1]));
  llvm::BasicBlock*& block =
      sharedSeq_[toLanding ? static_cast<std::int64_t>(inst.targets[1]) : -1];
  if (shared && block != nullptr) {
    return block;
  }
  const llvm::IRBuilderBase::InsertPointGuard guard(b_);
  llvm::BasicBlock* seq = newBlock("m99p");
  b_.SetInsertPoint(seq);
  if (shared) {
    at(firstLine_);
  }
  jumpToSeq(inst, b_.CreateLoad(abi_.f64, b_.CreateStructGEP(
                                              abi_.flow, flowSlot_, kFlowSeq)));
  if (shared) {
    block = seq;
  }
  return seq;
}

bool FunctionEmitter::blockHasPhis(ir::BlockId b) const {
  const std::vector<ir::ValueId>& insts = fn_.blocks[b].insts;
  return !insts.empty() && fn_.insts[insts.front()].op == ir::Op::Phi;
}

// M99 (return 0: mbc.resume set `leave`), the end of the run or an alarm.
llvm::BasicBlock* FunctionEmitter::leftBlock() {
  if (resumeStatus_) {
    return resumeStatus_->block();
  }
  const llvm::IRBuilderBase::InsertPointGuard guard(b_);
  llvm::BasicBlock* block = newBlock("left");
  b_.SetInsertPoint(block);
  at(firstLine_);
  resumeStatus_.emplace(b_, entry_, abi_.i32, "resumed", large_);
  llvm::Value* r = resumeStatus_->value();
  leave(b_.CreateSelect(
      b_.CreateICmpEQ(r, llvm::ConstantInt::get(abi_.i32, kResumeLeave)),
      llvm::ConstantInt::get(abi_.i32, 0), r));
  return block;
}

} // namespace mbc::codegen::detail
