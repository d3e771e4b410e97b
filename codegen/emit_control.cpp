// Emission of one function's control: the prologue, blocks and phis, and
// the terminators (computed GOTO, resume after NC blocks and calls, return),
// mirroring ir/evaluator.cpp. Every runtime status other than 0 leaves the
// function through one exit block, so alarms unwind as return values.
#include "codegen/emitter.h"
#include "ir/cfg.h"
#include <mbc/alarm.h>
#include <mbc/engine.h>

#include <llvm/IR/MDBuilder.h>

#include <set>

namespace mbc::codegen::detail {

FunctionEmitter::FunctionEmitter(ModuleState& m, const ir::Function& fn,
                                 llvm::Function* body)
    : m_(m), abi_(m.abi), fn_(fn), body_(body),
      large_(fn.insts.size() > kOptimizedSizeLimit), b_(m.abi.context) {
}

Handover::Handover(llvm::IRBuilder<>& b, llvm::BasicBlock* entry,
                   llvm::Type* type, const char* name, bool inMemory)
    : block_(b.GetInsertBlock()) {
  if (inMemory) {
    slot_ = llvm::IRBuilder<>(entry, entry->begin()).CreateAlloca(type);
    value_ = b.CreateLoad(type, slot_, name);
  } else {
    value_ = b.CreatePHI(type, 2, name);
  }
}

void Handover::add(llvm::IRBuilder<>& b, llvm::Value* v) {
  used_ = true;
  if (slot_ != nullptr) {
    b.CreateStore(v, slot_);
  } else {
    llvm::cast<llvm::PHINode>(value_)->addIncoming(v, b.GetInsertBlock());
  }
}

void FunctionEmitter::at(std::uint32_t line) {
  if (scope_ != nullptr) {
    b_.SetCurrentDebugLocation(m_.debug->location(line, scope_));
  }
}

// Instructions that passes made up without a line of their own (hoisted
// loads, say) belong to the program as a whole.
std::uint32_t FunctionEmitter::lineOf(const ir::Inst& inst) const {
  if (inst.op == ir::Op::Begin && inst.get<ir::SourceLine>().line > 0) {
    return inst.get<ir::SourceLine>().line;
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
  exitStatus_.emplace(b_, entry_, abi_.i32, "status", large_);
  b_.CreateRet(exitStatus_->value());
  b_.SetInsertPoint(entry_);
  emitPrologue();
  b_.CreateBr(blocks_[0]);
  // Reverse post-order emits every definition before its uses; blocks
  // that cannot be reached keep no code.
  ir::Cfg cfg = ir::buildCfg(fn_);
  findStaleFile(cfg);
  findRuns(cfg);
  for (ir::BlockId b : cfg.rpo) {
    if (runOf_[b] == kNoRun) {
      emitBlock(b);
    } else if (runs_[runOf_[b]].front() == b) {
      emitRun(runs_[runOf_[b]]);
    }
  }
  for (ir::BlockId b = 0; b < fn_.blocks.size(); ++b) {
    if (!cfg.reachable(b) ||
        (runOf_[b] != kNoRun && runs_[runOf_[b]].front() != b)) {
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
  if (!exitStatus_->used()) {
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
  blockFile_ = b_.CreateStructGEP(abi_.blockState, blockState_, kBlockFile);
  blockLine_ = b_.CreateStructGEP(abi_.blockState, blockState_, kBlockLine);
  blockCount_ = b_.CreateStructGEP(abi_.blockState, blockState_, kBlockCount);
  blockMax_ = b_.CreateStructGEP(abi_.blockState, blockState_, kBlockMax);
  file_ = m_.cstring(fn_.file);
  name_ = m_.cstring(fn_.name);
  flowSlot_ = b_.CreateAlloca(abi_.flow, nullptr, "flow");
  outSlot_ = b_.CreateAlloca(abi_.f64, nullptr, "out");
  retSeqSlot_ = b_.CreateAlloca(abi_.f64, nullptr, "retseq");
}

namespace {

// A resume of an NC block may make its call in mbc.resume.
bool staleAfter(ir::Op op, bool stale) {
  if (op == ir::Op::Begin) {
    return false;
  }
  return stale || op == ir::Op::CallMacro || op == ir::Op::Resume;
}

} // namespace

// Where the block state's file may not be this program's: on entry (it is
// the caller's) and after anything that may run another program, which
// only mbrt_run_call does (G65, and M98 or a code's call in mbc.resume).
// Nothing else writes it, so a begin stores the file only there; a
// forward may-dataflow over the IR's CFG.
void FunctionEmitter::findStaleFile(const ir::Cfg& cfg) {
  fileStaleIn_.assign(fn_.blocks.size(), 0);
  if (cfg.rpo.empty()) {
    return;
  }
  fileStaleIn_[cfg.rpo[0]] = 1;
  for (bool changed = true; changed;) {
    changed = false;
    for (ir::BlockId b : cfg.rpo) {
      bool stale = fileStaleIn_[b] != 0;
      for (ir::ValueId id : fn_.blocks[b].insts) {
        stale = staleAfter(fn_.insts[id].op, stale);
      }
      for (ir::BlockId s : cfg.succs[b]) {
        if (stale && fileStaleIn_[s] == 0) {
          fileStaleIn_[s] = 1;
          changed = true;
        }
      }
    }
  }
}

void FunctionEmitter::emitBlock(ir::BlockId b) {
  current_ = b;
  fileStale_ = fileStaleIn_[b] != 0;
  b_.SetInsertPoint(blocks_[b]);
  for (ir::ValueId id : fn_.blocks[b].insts) {
    const ir::Inst& inst = fn_.insts[id];
    at(lineOf(inst));
    if (inst.op == ir::Op::Phi) {
      emitInst(id);
    } else if (ir::opInfo(inst.op).flags & ir::Terminator) {
      flushAlarms();
      flushAdp();
      emitInst(id);
    } else {
      if (!isInlineValue(inst)) {
        flushAlarms();
      }
      if (!keepsAdpPending(inst)) {
        flushAdp();
      }
      emitInst(id);
      fileStale_ = staleAfter(inst.op, fileStale_);
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
        llvm::Value* v = inputFrom(phi, e.pred);
        if (v != nullptr) {
          node->addIncoming(v, e.from);
        }
      }
    }
  }
}

llvm::Value* FunctionEmitter::inputFrom(const ir::Inst& phi,
                                        ir::BlockId pred) const {
  for (std::size_t k = 0; k < phi.targets.size(); ++k) {
    if (phi.targets[k] == pred) {
      return values_[phi.ops[k]];
    }
  }
  return nullptr;
}

void FunctionEmitter::jump(ir::BlockId target) {
  incoming_[target].push_back({b_.GetInsertBlock(), current_});
  b_.CreateBr(blocks_[target]);
}

llvm::BasicBlock* FunctionEmitter::splitIf(llvm::Value* cond, bool unlikely) {
  llvm::BasicBlock* taken = newBlock("then");
  llvm::BasicBlock* rest = branchOff(cond, taken, unlikely);
  b_.SetInsertPoint(taken);
  return rest;
}

llvm::BasicBlock* FunctionEmitter::branchOff(llvm::Value* cond,
                                             llvm::BasicBlock* taken,
                                             bool unlikely) {
  llvm::BasicBlock* rest = newBlock("cont");
  llvm::MDNode* weights =
      unlikely ? llvm::MDBuilder(abi_.context).createBranchWeights(1, 2000)
               : nullptr;
  b_.CreateCondBr(cond, taken, rest, weights);
  b_.SetInsertPoint(rest);
  return rest;
}

void FunctionEmitter::leave(llvm::Value* status) {
  exitStatus_->add(b_, status);
  b_.CreateBr(exit_);
}

// Straight to the exit with the status: no block of its own per check.
void FunctionEmitter::check(llvm::Value* status) {
  exitStatus_->add(b_, status);
  branchOff(b_.CreateICmpNE(status, llvm::ConstantInt::get(abi_.i32, 0)), exit_,
            true);
}

void FunctionEmitter::raise(int alarmId, const char* detail) {
  llvm::Value* text = detail != nullptr
                          ? m_.cstring(detail)
                          : llvm::ConstantPointerNull::get(abi_.ptr);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise),
                      {ctx_, llvm::ConstantInt::get(abi_.i32, alarmId), text}));
}

void FunctionEmitter::leaveStopped(int endKind) {
  b_.CreateCall(abi_.fn(Rt::mbrt_finish),
                {ctx_, llvm::ConstantInt::get(abi_.i32, endKind)});
  leave(llvm::ConstantInt::get(abi_.i32, MBRT_STOP));
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

} // namespace mbc::codegen::detail
