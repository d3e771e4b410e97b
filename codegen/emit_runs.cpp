// Emission of runs of NC blocks whose words are all constants, the bulk of a
// posted part program: the blocks become a constant table of steps that one
// runtime call executes (mbrt_nc_steps), in a loop that gives mbc.resume the
// flow of a step that calls or leaves and goes on after it. Code per block
// made LLVM's time and memory grow with every block of the program (a
// 100 000-line program took minutes and gigabytes to compile).
#include "codegen/emitter.h"
#include <mbc/runtime.h>

namespace mbc::codegen::detail {

// A step: constants, one begin, one NC block of constant words that are not
// bare variables, and the resume that goes on to the next block.
bool FunctionEmitter::isStep(ir::BlockId b) const {
  const std::vector<ir::ValueId>& insts = fn_.blocks[b].insts;
  std::size_t begins = 0;
  ir::ValueId nc = ir::kNoValue;
  for (std::size_t k = 0; k + 1 < insts.size(); ++k) {
    const ir::Inst& inst = fn_.insts[insts[k]];
    if (inst.op == ir::Op::Begin && nc == ir::kNoValue) {
      ++begins;
    } else if (inst.op == ir::Op::Nc && begins == 1 && nc == ir::kNoValue) {
      nc = insts[k];
    } else if (inst.op != ir::Op::Const) {
      return false;
    }
  }
  if (begins != 1 || nc == ir::kNoValue || insts.empty()) {
    return false;
  }
  const ir::Inst& last = fn_.insts[insts.back()];
  if (last.op != ir::Op::Resume || last.ops[0] != nc ||
      last.targets.size() != 1) {
    return false;
  }
  const ir::Inst& block = fn_.insts[nc];
  const std::vector<ir::AddressWord>& words = block.get<ir::Words>().words;
  for (std::size_t k = 0; k < words.size(); ++k) {
    const ir::WordKind kind = words[k].kind;
    if (kind == ir::WordKind::Var || kind == ir::WordKind::NegVar ||
        fn_.insts[block.ops[k]].op != ir::Op::Const) {
      return false;
    }
  }
  return true;
}

// Chains of steps where each after the first has the one before as its only
// predecessor (so no jump, landing or phi lands inside), at least two long.
// Without debug information only: a run has one line for gdb.
void FunctionEmitter::findRuns(const ir::Cfg& cfg) {
  runOf_.assign(fn_.blocks.size(), kNoRun);
  if (m_.debug) {
    return;
  }
  for (ir::BlockId head : cfg.rpo) {
    if (runOf_[head] != kNoRun || !isStep(head)) {
      continue;
    }
    std::vector<ir::BlockId> run{head};
    for (ir::BlockId b = head;;) {
      const ir::BlockId next = fn_.insts[fn_.blocks[b].insts.back()].targets[0];
      if (next == cfg.rpo[0] || cfg.preds[next].size() != 1 ||
          runOf_[next] != kNoRun || next == head || !isStep(next)) {
        break;
      }
      run.push_back(next);
      b = next;
    }
    if (run.size() >= 2) {
      for (ir::BlockId b : run) {
        runOf_[b] = runs_.size();
      }
      runs_.push_back(std::move(run));
    }
  }
}

void FunctionEmitter::emitRun(const std::vector<ir::BlockId>& run) {
  current_ = run.back();
  b_.SetInsertPoint(blocks_[run.front()]);
  std::vector<std::int32_t> steps;
  std::vector<std::uint8_t> codes;
  std::vector<double> values;
  const ir::Inst* resume = nullptr;
  for (ir::BlockId b : run) {
    for (ir::ValueId id : fn_.blocks[b].insts) {
      const ir::Inst& inst = fn_.insts[id];
      if (inst.op == ir::Op::Const) {
        emitInst(id);
      } else if (inst.op == ir::Op::Begin) {
        steps.push_back(
            static_cast<std::int32_t>(inst.get<ir::SourceLine>().line));
      } else if (inst.op == ir::Op::Nc) {
        steps.push_back(static_cast<std::int32_t>(inst.ops.size()));
        steps.push_back(static_cast<std::int32_t>(values.size()));
        const std::vector<ir::AddressWord>& words = inst.get<ir::Words>().words;
        for (std::size_t k = 0; k < inst.ops.size(); ++k) {
          codes.push_back(static_cast<std::uint8_t>(words[k].letter));
          codes.push_back(runtimeWordKind(words[k].kind));
          values.push_back(fn_.insts[inst.ops[k]].get<ir::Number>().value);
        }
      } else {
        resume = &inst;
      }
    }
  }
  const std::size_t count = run.size();
  llvm::Constant* table = m_.constantData(
      llvm::ConstantStruct::get(
          abi_.ncRun,
          {llvm::cast<llvm::Constant>(file_),
           m_.constantData(llvm::ConstantDataArray::get(abi_.context, steps),
                           ".steps"),
           m_.constantData(llvm::ConstantDataArray::get(abi_.context, codes),
                           ".codes"),
           m_.constantData(llvm::ConstantDataArray::get(abi_.context, values),
                           ".values"),
           llvm::ConstantInt::get(abi_.i64, count)}),
      ".run");
  llvm::Value* nextSlot = scratch(abi_.i64, 1);

  llvm::BasicBlock* entry = b_.GetInsertBlock();
  llvm::BasicBlock* loop = newBlock("steps");
  b_.CreateBr(loop);
  b_.SetInsertPoint(loop);
  llvm::PHINode* first = b_.CreatePHI(abi_.i64, 2, "step");
  first->addIncoming(llvm::ConstantInt::get(abi_.i64, 0), entry);
  check(b_.CreateCall(abi_.fn(Rt::mbrt_nc_steps),
                      {ctx_, table, first, flowSlot_, nextSlot}));
  llvm::Value* after = b_.CreateLoad(abi_.i64, nextSlot, "after");
  llvm::Value* r = b_.CreateCall(m_.resume, {ctx_, flowSlot_, leave_});
  llvm::BasicBlock* left = leftBlock();
  resumeStatus_->add(b_, r);
  llvm::BasicBlock* goOn = newBlock("stepped");
  llvm::SwitchInst* sw = b_.CreateSwitch(r, left, 2);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, 0), goOn);
  sw->addCase(llvm::ConstantInt::get(abi_.i32, kResumeSeq), seqBlock(*resume));
  b_.SetInsertPoint(goOn);
  first->addIncoming(after, goOn);
  const ir::BlockId next = resume->targets[0];
  b_.CreateCondBr(
      b_.CreateICmpEQ(after, llvm::ConstantInt::get(abi_.i64, count)),
      blocks_[next], loop);
  incoming_[next].push_back({goOn, current_});
}

} // namespace mbc::codegen::detail
