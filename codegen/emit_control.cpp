// Emission of one function's control: the prologue, blocks and phis, and
// the terminators (computed GOTO, resume after NC blocks and calls, return),
// mirroring ir/evaluator.cpp. Every runtime status other than 0 leaves the
// function through one exit block, so alarms unwind as return values.
#include "codegen/emitter.h"
#include "ir/cfg.h"
#include <mbc/alarm.h>
#include <mbc/runtime.h>

#include <llvm/IR/MDBuilder.h>

#include <set>

namespace mbc::codegen::detail {

FunctionEmitter::FunctionEmitter(ModuleState& m, const ir::Function& fn,
                                 llvm::Function* body)
    : m_(m), abi_(m.abi), fn_(fn), body_(body), b_(m.abi.context) {
}

void FunctionEmitter::at(std::uint32_t line) {
  if (scope_ != nullptr) {
    b_.SetCurrentDebugLocation(m_.debug->location(line, scope_));
  }
}

// Instructions that passes made up without a line of their own (hoisted
// loads, say) belong to the program as a whole.
std::uint32_t FunctionEmitter::lineOf(const ir::Inst& inst) const {
  if (inst.op == ir::Op::Begin && inst.attr > 0) {
    return static_cast<std::uint32_t>(inst.attr);
  }
  return inst.line != 0 ? inst.line : firstLine_;
}

llvm::BasicBlock* FunctionEmitter::newBlock(const char* name) {
  return llvm::BasicBlock::Create(abi_.context, name, body_);
}

void FunctionEmitter::emit() {
  values_.assign(fn_.insts.size(), nullptr);
  incoming_.assign(fn_.blocks.size(), {});
  if (m_.debug) {
    scope_ = m_.debug->subprogram(body_, fn_);
    firstLine_ = DebugInfo::firstLine(fn_);
  }
  at(firstLine_);
  entry_ = newBlock("entry");
  for (std::size_t i = 0; i < fn_.blocks.size(); ++i) {
    blocks_.push_back(newBlock("b"));
  }
  exit_ = newBlock("exit");
  b_.SetInsertPoint(exit_);
  exitStatus_ = b_.CreatePHI(abi_.i32, 4, "status");
  b_.CreateRet(exitStatus_);
  b_.SetInsertPoint(entry_);
  emitPrologue();
  b_.CreateBr(blocks_[0]);
  // Reverse post-order emits every definition before its uses; blocks
  // that cannot be reached keep no code.
  ir::Cfg cfg = ir::buildCfg(fn_);
  for (ir::BlockId b : cfg.rpo) {
    emitBlock(b);
  }
  for (ir::BlockId b = 0; b < fn_.blocks.size(); ++b) {
    if (!cfg.reachable(b)) {
      b_.SetInsertPoint(blocks_[b]);
      b_.CreateUnreachable();
    }
  }
  fillPhis();
  for (auto& [type, slot] : scratch_) {
    slot.first->setOperand(
        0, llvm::ConstantInt::get(abi_.i32,
                                  std::max<std::size_t>(1, slot.second)));
  }
  if (exitStatus_->getNumIncomingValues() == 0) {
    exit_->eraseFromParent(); // a function that never leaves (an endless loop)
  }
}

// The context's storage, looked up once: levels never move while this
// activation runs, and the commons and block state live as long as the
// context.
void FunctionEmitter::emitPrologue() {
  ctx_ = body_->getArg(0);
  leave_ = body_->getArg(2);
  level_ = b_.CreateCall(abi_.fn(Rt::mbrt_current_level), {ctx_}, "level");
  commons_ = b_.CreateCall(abi_.fn(Rt::mbrt_common_base), {ctx_}, "commons");
  blockState_ =
      b_.CreateCall(abi_.fn(Rt::mbrt_block_state_of), {ctx_}, "blockstate");
  file_ = m_.cstring(fn_.file);
  name_ = m_.cstring(fn_.name);
  flowSlot_ = b_.CreateAlloca(abi_.flow, nullptr, "flow");
  outSlot_ = b_.CreateAlloca(abi_.f64, nullptr, "out");
}

void FunctionEmitter::emitBlock(ir::BlockId b) {
  current_ = b;
  b_.SetInsertPoint(blocks_[b]);
  for (ir::ValueId id : fn_.blocks[b].insts) {
    const ir::Inst& inst = fn_.insts[id];
    at(lineOf(inst));
    if (inst.op == ir::Op::Phi) {
      llvm::Type* type = inst.type == ir::Type::Bool ? abi_.i1 : abi_.f64;
      values_[id] = b_.CreatePHI(type, static_cast<unsigned>(inst.ops.size()));
    } else if (ir::opInfo(inst.op).flags & ir::Terminator) {
      emitTerminator(inst);
    } else {
      emitInst(id);
    }
  }
}

// Each recorded edge into a block gets the input its IR predecessor gives
// (a switch with several cases to one block gives one entry per case, as
// LLVM wants).
void FunctionEmitter::fillPhis() {
  for (ir::BlockId b = 0; b < fn_.blocks.size(); ++b) {
    for (ir::ValueId id : fn_.blocks[b].insts) {
      const ir::Inst& phi = fn_.insts[id];
      if (phi.op != ir::Op::Phi || values_[id] == nullptr) {
        break;
      }
      auto* node = llvm::cast<llvm::PHINode>(values_[id]);
      for (const Edge& e : incoming_[b]) {
        for (std::size_t k = 0; k < phi.targets.size(); ++k) {
          if (phi.targets[k] == e.pred) {
            node->addIncoming(values_[phi.ops[k]], e.from);
            break;
          }
        }
      }
    }
  }
}

void FunctionEmitter::jump(ir::BlockId target) {
  incoming_[target].push_back({b_.GetInsertBlock(), current_});
  b_.CreateBr(blocks_[target]);
}

llvm::BasicBlock* FunctionEmitter::splitIf(llvm::Value* cond, bool unlikely) {
  llvm::BasicBlock* taken = newBlock("then");
  llvm::BasicBlock* rest = newBlock("cont");
  llvm::MDNode* weights =
      unlikely ? llvm::MDBuilder(abi_.context).createBranchWeights(1, 2000)
               : nullptr;
  b_.CreateCondBr(cond, taken, rest, weights);
  b_.SetInsertPoint(taken);
  return rest;
}

void FunctionEmitter::leave(llvm::Value* status) {
  exitStatus_->addIncoming(status, b_.GetInsertBlock());
  b_.CreateBr(exit_);
}

void FunctionEmitter::check(llvm::Value* status) {
  llvm::BasicBlock* rest = splitIf(
      b_.CreateICmpNE(status, llvm::ConstantInt::get(abi_.i32, 0)), true);
  leave(status);
  b_.SetInsertPoint(rest);
}

void FunctionEmitter::raise(int alarmId, const char* detail) {
  llvm::Value* text = detail != nullptr
                          ? m_.cstring(detail)
                          : llvm::ConstantPointerNull::get(abi_.ptr);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise),
                      {ctx_, llvm::ConstantInt::get(abi_.i32, alarmId), text}));
}

void FunctionEmitter::alarmIf(llvm::Value* cond, int alarmId) {
  llvm::BasicBlock* rest = splitIf(cond, true);
  raise(alarmId, nullptr);
  b_.SetInsertPoint(rest);
}

void FunctionEmitter::leaveStopped(int endKind) {
  b_.CreateCall(abi_.fn(Rt::mbrt_finish),
                {ctx_, llvm::ConstantInt::get(abi_.i32, endKind)});
  leave(llvm::ConstantInt::get(abi_.i32, MBRT_STOP));
}

void FunctionEmitter::emitTerminator(const ir::Inst& inst) {
  switch (inst.op) {
    case ir::Op::Br:
      jump(inst.targets[0]);
      return;
    case ir::Op::CondBr: {
      llvm::BasicBlock* here = b_.GetInsertBlock();
      incoming_[inst.targets[0]].push_back({here, current_});
      incoming_[inst.targets[1]].push_back({here, current_});
      b_.CreateCondBr(values_[inst.ops[0]], blocks_[inst.targets[0]],
                      blocks_[inst.targets[1]]);
      return;
    }
    case ir::Op::Switch:
      emitSwitch(inst);
      return;
    case ir::Op::Resume:
      emitResume(inst);
      return;
    case ir::Op::Ret:
      emitRet();
      return;
    default:
      raise(static_cast<int>(AlarmId::Unsupported),
            "compiled code: unreachable code reached");
      return;
  }
}

// The end of a called program's text returns like M99; the end of the main
// program's text ends the run.
void FunctionEmitter::emitRet() {
  llvm::Value* depth = b_.CreateCall(abi_.fn(Rt::mbrt_call_depth), {ctx_});
  llvm::BasicBlock* called = splitIf(
      b_.CreateICmpEQ(depth, llvm::ConstantInt::get(abi_.i32, 0)), false);
  leaveStopped(MBRT_END_PROGRAM);
  b_.SetInsertPoint(called);
  leave(llvm::ConstantInt::get(abi_.i32, 0));
}

// Computed GOTO (evaluator switchTo).
void FunctionEmitter::emitSwitch(const ir::Inst& inst) {
  llvm::Value* target = numOperand(inst, 0);
  llvm::Value* n = roundHalfAway(target);
  llvm::Value* inRange = b_.CreateAnd(b_.CreateFCmpOGE(n, constant(1)),
                                      b_.CreateFCmpOLE(n, constant(99999)));
  llvm::BasicBlock* bad = newBlock("badgoto");
  llvm::BasicBlock* good = newBlock("goto");
  b_.CreateCondBr(inRange, good, bad);
  b_.SetInsertPoint(bad);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                      {ctx_, m_.cstring("GOTO "), target, name_}));
  b_.SetInsertPoint(good);
  emitCaseSwitch(inst, n, 0);
}

// M99 P from a callee: resume at that N of this function (evaluator
// jumpToSeq).
void FunctionEmitter::jumpToSeq(const ir::Inst& inst, llvm::Value* seq) {
  llvm::Value* n = roundHalfAway(seq);
  llvm::Value* inRange = b_.CreateAnd(b_.CreateFCmpOGE(n, constant(1)),
                                      b_.CreateFCmpOLE(n, constant(99999)));
  llvm::BasicBlock* bad = newBlock("badseq");
  llvm::BasicBlock* good = newBlock("seq");
  b_.CreateCondBr(inRange, good, bad);
  b_.SetInsertPoint(bad);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                      {ctx_, m_.cstring("M99 P"), seq, name_}));
  b_.SetInsertPoint(good);
  emitCaseSwitch(inst, n, 1);
}

// cases[i] goes to targets[i + offset]; a number without a case is PS0128.
// `n` is a whole number in 1..99999.
void FunctionEmitter::emitCaseSwitch(const ir::Inst& inst, llvm::Value* n,
                                     std::size_t offset) {
  llvm::BasicBlock* missing = newBlock("noseq");
  llvm::SwitchInst* sw =
      b_.CreateSwitch(b_.CreateFPToSI(n, abi_.i32), missing,
                      static_cast<unsigned>(inst.cases.size()));
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
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise_sequence),
                      {ctx_, m_.cstring(""), n, name_}));
}

// What an NC block or a call asks for next (evaluator resume, resumeNc). A
// call's flow is NEXT with has_seq for M99 P; so is an NC block's NEXT.
void FunctionEmitter::emitResume(const ir::Inst& inst) {
  llvm::Value* flow = values_[inst.ops[0]];
  llvm::Value* kind = b_.CreateExtractValue(flow, kFlowKind);
  llvm::BasicBlock* next = newBlock("next");
  llvm::BasicBlock* sub = newBlock("m98");
  llvm::BasicBlock* ret = newBlock("m99");
  llvm::BasicBlock* end = newBlock("end");
  llvm::SwitchInst* sw = b_.CreateSwitch(kind, next, 3);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, MBRT_FLOW_CALL_SUB), sub);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, MBRT_FLOW_RETURN), ret);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, MBRT_FLOW_END), end);

  b_.SetInsertPoint(next);
  llvm::BasicBlock* plain =
      splitIf(b_.CreateICmpNE(b_.CreateExtractValue(flow, kFlowHasSeq),
                              llvm::ConstantInt::get(abi_.i32, 0)),
              false);
  jumpToSeq(inst, b_.CreateExtractValue(flow, kFlowSeq));
  b_.SetInsertPoint(plain);
  jump(inst.targets[0]);

  b_.SetInsertPoint(sub);
  emitSubCall(inst, flow);

  // M99 in the main program ends a batch run (spec Part A).
  b_.SetInsertPoint(ret);
  llvm::Value* depth = b_.CreateCall(abi_.fn(Rt::mbrt_call_depth), {ctx_});
  llvm::BasicBlock* called = splitIf(
      b_.CreateICmpEQ(depth, llvm::ConstantInt::get(abi_.i32, 0)), false);
  leaveStopped(MBRT_END_MAIN_M99);
  b_.SetInsertPoint(called);
  b_.CreateStore(b_.CreateExtractValue(flow, kFlowHasSeq),
                 b_.CreateStructGEP(abi_.flow, leave_, kFlowHasSeq));
  b_.CreateStore(b_.CreateExtractValue(flow, kFlowSeq),
                 b_.CreateStructGEP(abi_.flow, leave_, kFlowSeq));
  leave(llvm::ConstantInt::get(abi_.i32, 0));

  b_.SetInsertPoint(end);
  llvm::Value* counts =
      b_.CreateICmpNE(b_.CreateExtractValue(flow, kFlowCountsPart),
                      llvm::ConstantInt::get(abi_.i32, 0));
  b_.CreateCall(
      abi_.fn(Rt::mbrt_finish),
      {ctx_, b_.CreateSelect(
                 counts, llvm::ConstantInt::get(abi_.i32, MBRT_END_M02_M30),
                 llvm::ConstantInt::get(abi_.i32, MBRT_END_PROGRAM))});
  leave(llvm::ConstantInt::get(abi_.i32, MBRT_STOP));
}

// M98 P L from an NC block: the subprogram on this call level.
void FunctionEmitter::emitSubCall(const ir::Inst& inst, llvm::Value* flow) {
  llvm::Value* program =
      b_.CreateSIToFP(b_.CreateExtractValue(flow, kFlowProgram), abi_.f64);
  llvm::Value* repeat =
      b_.CreateSIToFP(b_.CreateExtractValue(flow, kFlowRepeat), abi_.f64);
  check(b_.CreateCall(
      m_.dispatch, {ctx_, program, llvm::ConstantInt::get(abi_.i32, 0),
                    llvm::ConstantPointerNull::get(abi_.ptr),
                    llvm::ConstantInt::get(abi_.i64, 0), repeat, flowSlot_}));
  llvm::Value* out = loadFlow();
  llvm::BasicBlock* plain =
      splitIf(b_.CreateICmpNE(b_.CreateExtractValue(out, kFlowHasSeq),
                              llvm::ConstantInt::get(abi_.i32, 0)),
              false);
  jumpToSeq(inst, b_.CreateExtractValue(out, kFlowSeq));
  b_.SetInsertPoint(plain);
  jump(inst.targets[0]);
}

} // namespace mbc::codegen::detail
