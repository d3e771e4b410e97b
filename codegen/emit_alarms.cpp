// Emission of the alarm checks of arithmetic, builtins and the block
// counter. A check does not branch where it is made: the checks of a
// statement are gathered and tested by one branch before its first effect
// (a store, a call, the next block), so that a statement costs LLVM one
// block and one edge instead of one per operation. Only inline values come
// between a check and its branch, and they cannot fail or write anything,
// so the first check that holds gives the alarm, as if each had branched.
#include "codegen/emitter.h"

namespace mbc::codegen::detail {

bool FunctionEmitter::isInlineValue(const ir::Inst& inst) const {
  switch (inst.op) {
    case ir::Op::Const:
    case ir::Op::Vacant:
    case ir::Op::Add:
    case ir::Op::Sub:
    case ir::Op::Mul:
    case ir::Op::Div:
    case ir::Op::Neg:
    case ir::Op::ToNum:
    case ir::Op::Eq:
    case ir::Op::Ne:
    case ir::Op::Gt:
    case ir::Op::Ge:
    case ir::Op::Lt:
    case ir::Op::Le:
    case ir::Op::LogAnd:
    case ir::Op::LogOr:
    case ir::Op::LogXor:
    case ir::Op::RetSeq:
      return true;
    case ir::Op::Fn:
      return isInlineBuiltin(inst.get<ir::BuiltinFn>().fn);
    case ir::Op::LdVar:
      return isDirectVariable(inst.get<ir::VarNumber>().number);
    case ir::Op::Mod: // through the runtime
    case ir::Op::BitAnd:
    case ir::Op::BitOr:
    case ir::Op::BitXor:
    case ir::Op::RoundAddr:
    case ir::Op::Prm:
    case ir::Op::Phi:
    case ir::Op::BlockSkip:
    case ir::Op::StartSeq:
    case ir::Op::StVar:
    case ir::Op::LdInd:
    case ir::Op::StInd:
    case ir::Op::Adp:
    case ir::Op::Begin:
    case ir::Op::Nc:
    case ir::Op::CallMacro:
    case ir::Op::Dprnt:
    case ir::Op::Bprnt:
    case ir::Op::Popen:
    case ir::Op::Pclos:
    case ir::Op::Trace:
    case ir::Op::Br:
    case ir::Op::CondBr:
    case ir::Op::Switch:
    case ir::Op::Resume:
    case ir::Op::Ret:
    case ir::Op::Raise:
    case ir::Op::Unreachable:
      break;
  }
  return false;
}

void FunctionEmitter::alarmIf(llvm::Value* cond, int key) {
  if (auto* c = llvm::dyn_cast<llvm::ConstantInt>(cond); c && c->isZero()) {
    return;
  }
  llvm::Value* k = llvm::ConstantInt::get(abi_.i32, key);
  if (pendingFail_ == nullptr) {
    pendingFail_ = cond;
    pendingKey_ = k;
    return;
  }
  if (pendingKey_ != k) {
    pendingKey_ = b_.CreateSelect(pendingFail_, pendingKey_, k);
  }
  pendingFail_ = b_.CreateOr(pendingFail_, cond);
}

void FunctionEmitter::flushAlarms() {
  if (pendingFail_ == nullptr) {
    return;
  }
  llvm::Value* cond = pendingFail_;
  llvm::BasicBlock* fail = nullptr;
  if (auto* key = llvm::dyn_cast<llvm::ConstantInt>(pendingKey_)) {
    fail = failBlock(static_cast<int>(key->getSExtValue()));
  } else {
    fail = anyFailBlock();
    failKey_->add(b_, pendingKey_);
  }
  pendingFail_ = nullptr;
  pendingKey_ = nullptr;
  branchOff(cond, fail, true);
}

llvm::BasicBlock* FunctionEmitter::failBlock(int key) {
  if (key == kBlockLimit) {
    return sharedExit(Rt::mbrt_block_limit, {}, 0);
  }
  return sharedExit(Rt::mbrt_raise,
                    {llvm::ConstantInt::get(abi_.i32, key),
                     llvm::ConstantPointerNull::get(abi_.ptr)},
                    key);
}

// For the statements whose checks can fail in more than one way: the key
// of the first that failed comes in a phi.
llvm::BasicBlock* FunctionEmitter::anyFailBlock() {
  if (failKey_) {
    return failKey_->block();
  }
  const llvm::IRBuilderBase::InsertPointGuard guard(b_);
  llvm::BasicBlock* block = newBlock("fail");
  llvm::BasicBlock* raise = newBlock("raise");
  b_.SetInsertPoint(block);
  at(firstLine_);
  failKey_.emplace(b_, entry_, abi_.i32, "alarm", large_);
  llvm::Value* key = failKey_->value();
  b_.CreateCondBr(
      b_.CreateICmpEQ(key, llvm::ConstantInt::get(abi_.i32, kBlockLimit)),
      failBlock(kBlockLimit), raise);
  b_.SetInsertPoint(raise);
  leave(b_.CreateCall(abi_.fn(Rt::mbrt_raise),
                      {ctx_, key, llvm::ConstantPointerNull::get(abi_.ptr)}));
  return block;
}

llvm::BasicBlock*
FunctionEmitter::sharedExit(Rt f, std::vector<llvm::Value*> args, int key) {
  llvm::BasicBlock*& block = sharedExits_[{f, key}];
  if (block == nullptr) {
    const llvm::IRBuilderBase::InsertPointGuard guard(b_);
    block = newBlock("fail");
    b_.SetInsertPoint(block);
    // Shared by many lines: the function's first line in debug info.
    at(firstLine_);
    args.insert(args.begin(), ctx_);
    leave(b_.CreateCall(abi_.fn(f), args));
  }
  return block;
}

} // namespace mbc::codegen::detail
