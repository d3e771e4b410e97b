// Emission of values: constants, FANUC arithmetic with its alarms,
// comparisons that tell vacant from 0, and the builtins (the cheap ones
// inline, the others through the runtime), mirroring mbc/arith.h exactly so
// that every engine computes the same bits.
#include "codegen/emitter.h"
#include <mbc/alarm.h>
#include <mbc/arith.h>
#include <mbc/value.h>

#include <llvm/IR/Intrinsics.h>

#include <limits>

namespace mbc::codegen::detail {

namespace {

int alarm(AlarmId id) {
  return static_cast<int>(id);
}

} // namespace

llvm::Value* FunctionEmitter::constant(double x) {
  return llvm::ConstantFP::get(abi_.f64, x);
}

llvm::Value* FunctionEmitter::isVacant(llvm::Value* x) {
  return b_.CreateFCmpUNO(x, x); // vacant is the only NaN a value can be
}

llvm::Value* FunctionEmitter::toNum(llvm::Value* x) {
  return b_.CreateSelect(isVacant(x), constant(0), x);
}

llvm::Value* FunctionEmitter::numOperand(const ir::Inst& inst, std::size_t i) {
  ir::ValueId v = inst.ops[i];
  return fn_.insts[v].type == ir::Type::VNum ? toNum(values_[v]) : values_[v];
}

// No macro value is ever -0.0 (mbc/arith.cpp): x + 0.0 turns -0.0 into
// +0.0 and leaves everything else alone.
llvm::Value* FunctionEmitter::positiveZero(llvm::Value* x) {
  return b_.CreateFAdd(x, constant(0));
}

llvm::Value* FunctionEmitter::roundHalfAway(llvm::Value* x) {
  return b_.CreateUnaryIntrinsic(llvm::Intrinsic::round, x);
}

// Arithmetic on finite operands overflows to infinity, never to NaN: PS0111.
// Two compares rather than one on fabs: FastISel (-O0) selects no fabs and
// gave the rest of the block to SelectionDAG; InstCombine folds them back.
llvm::Value* FunctionEmitter::finite(llvm::Value* result) {
  const double inf = std::numeric_limits<double>::infinity();
  llvm::Value* positive = b_.CreateFCmpOEQ(result, constant(inf));
  llvm::Value* negative = b_.CreateFCmpOEQ(result, constant(-inf));
  alarmIf(b_.CreateOr(positive, negative), alarm(AlarmId::FloatOverflow));
  return result;
}

llvm::Value* FunctionEmitter::callStatusOut(Rt f,
                                            std::vector<llvm::Value*> args) {
  args.push_back(outSlot_);
  check(b_.CreateCall(abi_.fn(f), args));
  return b_.CreateLoad(abi_.f64, outSlot_);
}

// evalBinary's + - * / inline: the same IEEE operations, then its checks;
// MOD and the bit operations through the runtime.
llvm::Value* FunctionEmitter::emitArith(const ir::Inst& inst, BinOp op) {
  llvm::Value* a = numOperand(inst, 0);
  llvm::Value* b = numOperand(inst, 1);
  switch (op) {
    case BinOp::Add: // the sum of two values that are not -0.0 is not -0.0
      return finite(b_.CreateFAdd(a, b));
    case BinOp::Sub:
      return finite(b_.CreateFSub(a, b));
    case BinOp::Mul:
      return finite(positiveZero(b_.CreateFMul(a, b)));
    case BinOp::Div:
      alarmIf(b_.CreateFCmpOEQ(b, constant(0)), alarm(AlarmId::ZeroDivide));
      return finite(positiveZero(b_.CreateFDiv(a, b)));
    case BinOp::Mod:
    case BinOp::And:
    case BinOp::Or:
    case BinOp::Xor:
      break;
  }
  return callStatusOut(
      Rt::mbrt_binary,
      {ctx_, llvm::ConstantInt::get(abi_.i32, static_cast<std::uint64_t>(op)),
       a, b});
}

// evalCompare: EQ and NE tell vacant from 0 (vacant EQ vacant); a num is
// never vacant, so an ordered compare suffices unless both may be.
llvm::Value* FunctionEmitter::emitCompare(const ir::Inst& inst, RelOp op) {
  if (op == RelOp::Eq || op == RelOp::Ne) {
    llvm::Value* a = values_[inst.ops[0]];
    llvm::Value* b = values_[inst.ops[1]];
    llvm::Value* equal = b_.CreateFCmpOEQ(a, b);
    if (fn_.insts[inst.ops[0]].type == ir::Type::VNum &&
        fn_.insts[inst.ops[1]].type == ir::Type::VNum) {
      equal = b_.CreateOr(equal, b_.CreateAnd(isVacant(a), isVacant(b)));
    }
    return op == RelOp::Eq ? equal : b_.CreateNot(equal);
  }
  llvm::Value* a = numOperand(inst, 0);
  llvm::Value* b = numOperand(inst, 1);
  switch (op) {
    case RelOp::Gt:
      return b_.CreateFCmpOGT(a, b);
    case RelOp::Ge:
      return b_.CreateFCmpOGE(a, b);
    case RelOp::Lt:
      return b_.CreateFCmpOLT(a, b);
    case RelOp::Le:
    case RelOp::Eq:
    case RelOp::Ne:
      break;
  }
  return b_.CreateFCmpOLE(a, b);
}

bool isInlineBuiltin(Builtin f) {
  switch (f) {
    case Builtin::Abs:
    case Builtin::Round:
    case Builtin::Fix:
    case Builtin::Fup:
    case Builtin::Sqrt:
    case Builtin::Adp:
      return true;
    default:
      return false;
  }
}

// The rounding functions, ABS and SQRT inline (exact IEEE operations, as in
// evalBuiltin); the trigonometric and other functions through the runtime.
llvm::Value* FunctionEmitter::emitFn(const ir::Inst& inst) {
  const Builtin f = inst.get<ir::BuiltinFn>().fn;
  llvm::Value* x = numOperand(inst, 0);
  if (!isInlineBuiltin(f)) {
    llvm::Value* y = inst.ops.size() > 1 ? numOperand(inst, 1) : constant(0);
    return callStatusOut(
        Rt::mbrt_builtin,
        {ctx_, llvm::ConstantInt::get(abi_.i32, static_cast<std::uint64_t>(f)),
         x, y});
  }
  switch (f) {
    case Builtin::Abs:
      return b_.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, x);
    case Builtin::Round:
      return positiveZero(roundHalfAway(x));
    case Builtin::Fix:
      return positiveZero(b_.CreateUnaryIntrinsic(llvm::Intrinsic::trunc, x));
    case Builtin::Fup:
      return b_.CreateSelect(b_.CreateFCmpOLT(x, constant(0)),
                             b_.CreateUnaryIntrinsic(llvm::Intrinsic::floor, x),
                             b_.CreateUnaryIntrinsic(llvm::Intrinsic::ceil, x));
    case Builtin::Sqrt:
      alarmIf(b_.CreateFCmpOLT(x, constant(0)),
              alarm(AlarmId::ArgumentOutOfRange));
      return b_.CreateUnaryIntrinsic(llvm::Intrinsic::sqrt, x);
    default: // ADP of a value that is not a variable
      return x;
  }
}

} // namespace mbc::codegen::detail
