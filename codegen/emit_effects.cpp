// Emission of variables and effects: locals and commons as direct loads and
// stores in the context, other variables through the runtime, the block
// counter inline, and NC blocks, G65 calls, DPRNT/BPRNT and trace lines as
// runtime calls (ir/evaluator_ops.cpp does the same one by one).
#include "codegen/emitter.h"
#include <mbc/alarm.h>
#include <mbc/engine.h>
#include <mbc/limits.h>

namespace mbc::codegen::detail {

bool isDirectVariable(std::int64_t n) {
  return isLocal(n) || isFixedCommon(n);
}

// mbrt_begin_block inline: where alarms and motion are reported, and the
// execution limit. The limit is loaded at every block: a signal handler or
// another thread lowers it to stop the run (mbrt_interrupt), and a plain
// load would be hoisted out of a loop that calls nothing. A volatile load of
// an aligned word is one untorn move on the targets LLVM builds for, as the
// monotonic load it replaces was; FastISel (-O0 and optnone bodies) cannot
// select an atomic load and handed the rest of every block to SelectionDAG.
void FunctionEmitter::emitBegin(const ir::Inst& inst) {
  if (fileStale_) {
    b_.CreateStore(file_, blockFile_);
  }
  b_.CreateStore(
      llvm::ConstantInt::get(abi_.i32, inst.get<ir::SourceLine>().line),
      blockLine_);
  llvm::Value* count = b_.CreateAdd(b_.CreateLoad(abi_.i64, blockCount_),
                                    llvm::ConstantInt::get(abi_.i64, 1));
  b_.CreateStore(count, blockCount_);
  llvm::LoadInst* max =
      b_.CreateAlignedLoad(abi_.i64, blockMax_, llvm::Align(8), true);
  alarmIf(b_.CreateICmpUGT(count, max), kBlockLimit);
}

llvm::Value* FunctionEmitter::localSlot(llvm::Value* index) {
  return b_.CreateInBoundsGEP(abi_.level, level_,
                              {llvm::ConstantInt::get(abi_.i32, 0),
                               llvm::ConstantInt::get(abi_.i32, kLevelValue),
                               index});
}

// A program's own write of a local clears its ADP flag.
void FunctionEmitter::clearAdp(llvm::Value* index) {
  clearAdpBits(b_.CreateShl(llvm::ConstantInt::get(abi_.i64, 1), index));
}

void FunctionEmitter::clearAdpBits(llvm::Value* bits) {
  llvm::Value* slot = b_.CreateStructGEP(abi_.level, level_, kLevelAdpMask);
  b_.CreateStore(
      b_.CreateAnd(b_.CreateLoad(abi_.i64, slot), b_.CreateNot(bits)), slot);
}

// Only ADP[] (the runtime) and the programs a call runs read the flags, so
// the writes of locals by number clear theirs together before the next
// instruction that may: one read-modify-write for a run of statements.
void FunctionEmitter::flushAdp() {
  if (pendingAdp_ != 0) {
    clearAdpBits(llvm::ConstantInt::get(abi_.i64, pendingAdp_));
    pendingAdp_ = 0;
  }
}

bool FunctionEmitter::keepsAdpPending(const ir::Inst& inst) const {
  return inst.op == ir::Op::Begin ||
         (inst.op == ir::Op::StVar &&
          isDirectVariable(inst.get<ir::VarNumber>().number)) ||
         isInlineValue(inst);
}

llvm::Value* FunctionEmitter::commonSlot(llvm::Value* number) {
  return b_.CreateInBoundsGEP(abi_.f64, commons_, number);
}

llvm::Value* FunctionEmitter::message(ir::StringRef ref) {
  const std::string* s = m_.ir.text(ref);
  if (s == nullptr || s->empty()) {
    return llvm::ConstantPointerNull::get(abi_.ptr);
  }
  return m_.cstring(*s);
}

llvm::Value* FunctionEmitter::emitLoadVar(int number) {
  if (isLocal(number)) {
    return b_.CreateLoad(
        abi_.f64, localSlot(llvm::ConstantInt::get(abi_.i64, number - 1)));
  }
  if (isFixedCommon(number)) {
    return b_.CreateLoad(abi_.f64,
                         commonSlot(llvm::ConstantInt::get(abi_.i64, number)));
  }
  return callStatusOut(Rt::mbrt_read_var, {ctx_, constant(number)});
}

void FunctionEmitter::emitStoreVar(const ir::Inst& inst, int number,
                                   llvm::Value* value) {
  if (isLocal(number)) {
    b_.CreateStore(value,
                   localSlot(llvm::ConstantInt::get(abi_.i64, number - 1)));
    pendingAdp_ |= std::uint64_t{1} << (number - 1);
    return;
  }
  if (isFixedCommon(number)) {
    b_.CreateStore(value, commonSlot(llvm::ConstantInt::get(abi_.i64, number)));
    return;
  }
  check(b_.CreateCall(abi_.fn(Rt::mbrt_write_var),
                      {ctx_, constant(number), value,
                       message(inst.get<ir::VarNumber>().message)}));
}

namespace {

/// Where #[x] lives: n is the rounded number (-1 beyond any variable).
struct IndirectCases {
  llvm::Value* n;
  llvm::Value* isLocal;
  llvm::Value* isCommon;
};

IndirectCases classify(llvm::IRBuilder<>& b, const Abi& abi, llvm::Value* x) {
  llvm::Value* r = b.CreateUnaryIntrinsic(llvm::Intrinsic::round, x);
  llvm::Value* small =
      b.CreateFCmpOLT(b.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, r),
                      llvm::ConstantFP::get(abi.f64, kBeyondAnyVariable));
  llvm::Value* n = b.CreateSelect(small, b.CreateFPToSI(r, abi.i64),
                                  llvm::ConstantInt::get(abi.i64, -1));
  auto within = [&](std::int64_t lo, std::int64_t count) {
    return b.CreateICmpULT(b.CreateSub(n, llvm::ConstantInt::get(abi.i64, lo)),
                           llvm::ConstantInt::get(abi.i64, count));
  };
  // #200..#499 depend on the profile and go through the runtime.
  return {n, within(kFirstLocal, kLocalCount),
          b.CreateOr(within(kFirstCommon, kLastCommon - kFirstCommon + 1),
                     within(kFirstNonvolatile,
                            kLastNonvolatile - kFirstNonvolatile + 1))};
}

} // namespace

// #[x]: locals and commons inline, every other number through the runtime
// (which rounds and range-checks it again). Each way gives the value of a
// load, or nullptr for a store.
llvm::Value* FunctionEmitter::indirect(llvm::Value* x,
                                       const IndirectWays& ways) {
  IndirectCases c = classify(b_, abi_, x);
  llvm::BasicBlock* local = newBlock("local");
  llvm::BasicBlock* other = newBlock("other");
  llvm::BasicBlock* common = newBlock("common");
  llvm::BasicBlock* slow = newBlock("runtime");
  llvm::BasicBlock* done = newBlock("var");
  b_.CreateCondBr(c.isLocal, local, other);
  b_.SetInsertPoint(local);
  llvm::Value* fromLocal =
      ways.local(b_.CreateSub(c.n, llvm::ConstantInt::get(abi_.i64, 1)));
  b_.CreateBr(done);
  b_.SetInsertPoint(other);
  b_.CreateCondBr(c.isCommon, common, slow);
  b_.SetInsertPoint(common);
  llvm::Value* fromCommon = ways.common(c.n);
  b_.CreateBr(done);
  b_.SetInsertPoint(slow);
  llvm::Value* fromRuntime = ways.runtime();
  llvm::BasicBlock* slowEnd = b_.GetInsertBlock();
  b_.CreateBr(done);
  b_.SetInsertPoint(done);
  if (fromLocal == nullptr) {
    return nullptr;
  }
  llvm::PHINode* v = b_.CreatePHI(abi_.f64, 3);
  v->addIncoming(fromLocal, local);
  v->addIncoming(fromCommon, common);
  v->addIncoming(fromRuntime, slowEnd);
  return v;
}

llvm::Value* FunctionEmitter::emitLoadIndirect(llvm::Value* x) {
  return indirect(x, {[&](llvm::Value* index) {
                        return b_.CreateLoad(abi_.f64, localSlot(index));
                      },
                      [&](llvm::Value* n) {
                        return b_.CreateLoad(abi_.f64, commonSlot(n));
                      },
                      [&] {
                        return callStatusOut(Rt::mbrt_read_var, {ctx_, x});
                      }});
}

void FunctionEmitter::emitStoreIndirect(const ir::Inst& inst, llvm::Value* x,
                                        llvm::Value* value) {
  indirect(x, {[&](llvm::Value* index) -> llvm::Value* {
                 b_.CreateStore(value, localSlot(index));
                 clearAdp(index);
                 return nullptr;
               },
               [&](llvm::Value* n) -> llvm::Value* {
                 b_.CreateStore(value, commonSlot(n));
                 return nullptr;
               },
               [&]() -> llvm::Value* {
                 check(b_.CreateCall(
                     abi_.fn(Rt::mbrt_write_var),
                     {ctx_, x, value, message(inst.get<ir::Message>().text)}));
                 return nullptr;
               }});
}

// One buffer per struct type serves every statement of the function: the
// runtime reads it during the call only. Its size is fixed in emit().
llvm::Value* FunctionEmitter::scratch(llvm::Type* type, std::size_t count) {
  auto it = scratch_.find(type);
  if (it == scratch_.end()) {
    llvm::IRBuilder<> entry(entry_, entry_->begin());
    llvm::AllocaInst* slot =
        entry.CreateAlloca(type, llvm::ConstantInt::get(abi_.i32, 1));
    it = scratch_.emplace(type, std::make_pair(slot, std::size_t{0})).first;
  }
  it->second.second = std::max(it->second.second, count);
  return it->second.first;
}

llvm::Value* FunctionEmitter::loadFlow() {
  return b_.CreateLoad(abi_.flow, flowSlot_);
}

// The words of nc (first = 0) or call.macro (first = 2: after P and L): a
// bare vacant variable drops its word (spec §2.3a), any other value reads
// vacant as 0. Words that are all constants (the blocks of a posted part
// program) are one constant array: no stores, and no constant-pool entry per
// value, which LLVM finds by a linear search.
FunctionEmitter::Words FunctionEmitter::buildWords(const ir::Inst& inst) {
  /// One word: its fields, and whether a vacant value drops it.
  struct Word {
    llvm::Constant* letter;
    llvm::Constant* kind;
    llvm::Value* value;
    bool mayDrop;
  };

  const std::vector<ir::AddressWord>& descs = inst.get<ir::Words>().words;
  const std::size_t first = ir::firstWordOperand(inst.op);
  std::vector<Word> words;
  std::vector<llvm::Constant*> fixed;
  for (std::size_t k = first; k < inst.ops.size(); ++k) {
    const ir::AddressWord& desc = descs[k - first];
    ir::WordKind kind = desc.kind;
    bool bare = kind == ir::WordKind::Var || kind == ir::WordKind::NegVar;
    llvm::Value* value = values_[inst.ops[k]];
    if (!bare) {
      value = numOperand(inst, k);
    } else if (kind == ir::WordKind::NegVar) {
      value = b_.CreateFSub(constant(0), value); // vacant stays NaN
    }
    const Word word{llvm::ConstantInt::get(abi_.i8, desc.letter),
                    llvm::ConstantInt::get(abi_.i8, runtimeWordKind(kind)),
                    value,
                    bare && fn_.insts[inst.ops[k]].type == ir::Type::VNum};
    words.push_back(word);
    auto* c = llvm::dyn_cast<llvm::ConstantFP>(value);
    if (c != nullptr && !bare) {
      fixed.push_back(
          llvm::ConstantStruct::get(abi_.word, {word.letter, word.kind, c}));
    }
  }
  if (fixed.size() == words.size()) {
    return {m_.constantWords(fixed),
            llvm::ConstantInt::get(abi_.i64, fixed.size())};
  }
  llvm::Value* buffer = scratch(abi_.word, words.size());
  llvm::Value* count = llvm::ConstantInt::get(abi_.i64, 0);
  for (const Word& word : words) {
    llvm::Value* slot = b_.CreateInBoundsGEP(abi_.word, buffer, count);
    b_.CreateStore(word.letter,
                   b_.CreateStructGEP(abi_.word, slot, kWordLetter));
    b_.CreateStore(word.kind, b_.CreateStructGEP(abi_.word, slot, kWordKind));
    b_.CreateStore(word.value, b_.CreateStructGEP(abi_.word, slot, kWordValue));
    llvm::Value* present =
        word.mayDrop
            ? b_.CreateZExt(b_.CreateNot(isVacant(word.value)), abi_.i64)
            : llvm::ConstantInt::get(abi_.i64, 1);
    count = b_.CreateAdd(count, present);
  }
  return {buffer, count};
}

llvm::Value* FunctionEmitter::emitNc(const ir::Inst& inst) {
  const Words words = buildWords(inst);
  check(b_.CreateCall(abi_.fn(Rt::mbrt_nc_block),
                      {ctx_, words.data, words.count, flowSlot_}));
  return loadFlow();
}

// G65 (evaluator execCallMacro): P and L are operands 0 and 1. The call's
// flow is NEXT, with has_seq/seq when the callee left by M99 P.
llvm::Value* FunctionEmitter::emitCallMacro(const ir::Inst& inst) {
  llvm::Value* p = numOperand(inst, 0);
  llvm::Value* l = numOperand(inst, 1);
  const Words words = buildWords(inst);
  b_.CreateCall(abi_.fn(Rt::mbrt_trace_call),
                {ctx_, p, l, words.data, words.count});
  check(b_.CreateCall(m_.dispatch,
                      {ctx_, p, llvm::ConstantInt::get(abi_.i32, 1), words.data,
                       words.count, l, constant(0), flowSlot_}));
  return b_.CreateInsertValue(
      loadFlow(), llvm::ConstantInt::get(abi_.i32, MBRT_FLOW_NEXT), kFlowKind);
}

void FunctionEmitter::emitPrint(const ir::Inst& inst) {
  const std::vector<ir::PrintItem>& list = inst.get<ir::PrintItems>().items;
  llvm::Value* items = scratch(abi_.printItem, list.size());
  std::size_t next = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ir::PrintItem& item = list[i];
    llvm::Value* slot = b_.CreateConstInBoundsGEP1_64(abi_.printItem, items, i);
    llvm::Value* text = llvm::ConstantPointerNull::get(abi_.ptr);
    llvm::Value* value = constant(0);
    if (item.isValue()) {
      value = values_[inst.ops[next++]];
    } else {
      text = m_.cstring(*m_.ir.text(item.text));
    }
    b_.CreateStore(text, b_.CreateStructGEP(abi_.printItem, slot, kItemText));
    b_.CreateStore(value, b_.CreateStructGEP(abi_.printItem, slot, kItemValue));
    b_.CreateStore(llvm::ConstantInt::get(abi_.i32, item.intDigits),
                   b_.CreateStructGEP(abi_.printItem, slot, kItemIntDigits));
    b_.CreateStore(llvm::ConstantInt::get(abi_.i32, item.fracDigits),
                   b_.CreateStructGEP(abi_.printItem, slot, kItemFracDigits));
  }
  Rt f = inst.op == ir::Op::Dprnt ? Rt::mbrt_dprnt : Rt::mbrt_bprnt;
  check(b_.CreateCall(
      abi_.fn(f),
      {ctx_, items, llvm::ConstantInt::get(abi_.i64, list.size())}));
}

// Only while a trace sink is set: code compiled with trace statements (all
// of `mbc build`'s) runs at full speed without --trace.
void FunctionEmitter::emitTrace(const ir::Inst& inst) {
  llvm::Value* tracing =
      b_.CreateLoad(abi_.i32, b_.CreateStructGEP(abi_.blockState, blockState_,
                                                 kBlockTracing));
  llvm::BasicBlock* rest = splitIf(
      b_.CreateICmpNE(tracing, llvm::ConstantInt::get(abi_.i32, 0)), true);
  llvm::Value* values = scratch(abi_.f64, inst.ops.size());
  for (std::size_t i = 0; i < inst.ops.size(); ++i) {
    llvm::Value* v = values_[inst.ops[i]];
    if (v->getType() == abi_.i1) {
      v = b_.CreateUIToFP(v, abi_.f64);
    }
    b_.CreateStore(v, b_.CreateConstInBoundsGEP1_64(abi_.f64, values, i));
  }
  b_.CreateCall(abi_.fn(Rt::mbrt_trace_values),
                {ctx_, message(inst.get<ir::Message>().text), values,
                 llvm::ConstantInt::get(abi_.i64, inst.ops.size())});
  b_.CreateBr(rest);
  b_.SetInsertPoint(rest);
}

} // namespace mbc::codegen::detail
