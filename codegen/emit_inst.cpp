// The one switch over every IR operation in codegen: -Wswitch names any
// operation added to ir/opcodes.def that compiled code does not emit yet.
// The cases hand the work to the emitters of values, effects and transfers.
#include "codegen/emitter.h"
#include <mbc/alarm.h>
#include <mbc/value.h>

namespace mbc::codegen::detail {

void FunctionEmitter::emitInst(ir::ValueId id) {
  values_[id] = emitOp(fn_.insts[id]);
}

llvm::Value* FunctionEmitter::emitOp(const ir::Inst& inst) {
  switch (inst.op) {
    case ir::Op::Const:
      return constant(inst.get<ir::Number>().value);
    case ir::Op::Vacant:
      return llvm::ConstantFP::get(abi_.context,
                                   llvm::APFloat(llvm::APFloat::IEEEdouble(),
                                                 llvm::APInt(64, kVacantBits)));
    case ir::Op::Add:
    case ir::Op::Sub:
    case ir::Op::Mul:
    case ir::Op::Div:
    case ir::Op::Mod:
    case ir::Op::BitAnd:
    case ir::Op::BitOr:
    case ir::Op::BitXor:
      return emitArith(inst, *ir::binaryOf(inst.op));
    case ir::Op::Neg: // 0 - x is -x without -0.0
      return b_.CreateFSub(constant(0), numOperand(inst, 0));
    case ir::Op::ToNum:
      return toNum(values_[inst.ops[0]]);
    case ir::Op::Fn:
      return emitFn(inst);
    case ir::Op::Prm:
      return callStatusOut(
          Rt::mbrt_read_parameter,
          {ctx_,
           llvm::ConstantInt::get(
               abi_.i32, static_cast<int>(inst.get<ir::Number>().value)),
           numOperand(inst, 0), numOperand(inst, 1), numOperand(inst, 2)});
    case ir::Op::RoundAddr:
      return callStatusOut(Rt::mbrt_round_address,
                           {ctx_,
                            llvm::ConstantInt::get(
                                abi_.i32, inst.get<ir::AddressLetter>().letter),
                            numOperand(inst, 0)});
    case ir::Op::Eq:
    case ir::Op::Ne:
    case ir::Op::Gt:
    case ir::Op::Ge:
    case ir::Op::Lt:
    case ir::Op::Le:
      return emitCompare(inst, *ir::relationOf(inst.op));
    case ir::Op::LogAnd:
      return b_.CreateAnd(values_[inst.ops[0]], values_[inst.ops[1]]);
    case ir::Op::LogOr:
      return b_.CreateOr(values_[inst.ops[0]], values_[inst.ops[1]]);
    case ir::Op::LogXor:
      return b_.CreateXor(values_[inst.ops[0]], values_[inst.ops[1]]);
    case ir::Op::Phi: // fillPhis adds the inputs once every block is emitted
      return b_.CreatePHI(inst.type == ir::Type::Bool ? abi_.i1 : abi_.f64,
                          static_cast<unsigned>(inst.ops.size()));
    case ir::Op::RetSeq:
      return b_.CreateLoad(abi_.f64, retSeqSlot_);
    case ir::Op::StartSeq:
      return b_.CreateCall(abi_.fn(Rt::mbrt_entry_sequence), {ctx_});
    case ir::Op::BlockSkip:
      return b_.CreateICmpNE(
          b_.CreateCall(
              abi_.fn(Rt::mbrt_skip_switch),
              {ctx_, llvm::ConstantInt::get(
                         abi_.i32, inst.get<ir::SkipSwitch>().number)}),
          llvm::ConstantInt::get(abi_.i32, 0));
    case ir::Op::LdVar:
      return emitLoadVar(static_cast<int>(inst.get<ir::VarNumber>().number));
    case ir::Op::StVar:
      emitStoreVar(inst, static_cast<int>(inst.get<ir::VarNumber>().number),
                   values_[inst.ops[0]]);
      return nullptr;
    case ir::Op::LdInd:
      return emitLoadIndirect(numOperand(inst, 0));
    case ir::Op::StInd:
      emitStoreIndirect(inst, numOperand(inst, 0), values_[inst.ops[1]]);
      return nullptr;
    case ir::Op::Adp:
      return callStatusOut(Rt::mbrt_adp, {ctx_, numOperand(inst, 0)});
    case ir::Op::Begin:
      emitBegin(inst);
      return nullptr;
    case ir::Op::Nc:
      return emitNc(inst);
    case ir::Op::CallMacro:
      return emitCallMacro(inst);
    case ir::Op::Dprnt:
    case ir::Op::Bprnt:
      emitPrint(inst);
      return nullptr;
    case ir::Op::Popen:
      check(b_.CreateCall(abi_.fn(Rt::mbrt_popen), {ctx_}));
      return nullptr;
    case ir::Op::Pclos:
      check(b_.CreateCall(abi_.fn(Rt::mbrt_pclos), {ctx_}));
      return nullptr;
    case ir::Op::Trace:
      emitTrace(inst);
      return nullptr;
    case ir::Op::Br:
      jump(inst.targets[0]);
      return nullptr;
    case ir::Op::CondBr: {
      llvm::BasicBlock* here = b_.GetInsertBlock();
      incoming_[inst.targets[0]].push_back({here, current_});
      incoming_[inst.targets[1]].push_back({here, current_});
      b_.CreateCondBr(values_[inst.ops[0]], blocks_[inst.targets[0]],
                      blocks_[inst.targets[1]]);
      return nullptr;
    }
    case ir::Op::Switch:
      emitSwitch(inst);
      return nullptr;
    case ir::Op::Resume:
      emitResume(inst);
      return nullptr;
    case ir::Op::Ret:
      emitRet();
      return nullptr;
    case ir::Op::Raise: {
      const ir::AlarmRaise& r = inst.get<ir::AlarmRaise>();
      raise(static_cast<int>(r.alarm),
            r.detail != 0 ? m_.ir.text(r.detail)->c_str() : nullptr);
      return nullptr;
    }
    case ir::Op::Unreachable:
      raise(static_cast<int>(AlarmId::InternalError),
            "compiled code: unreachable code reached");
      return nullptr;
  }
  // Only a value outside the enumeration gets here.
  raise(static_cast<int>(AlarmId::InternalError),
        "compiled code: unknown operation");
  b_.SetInsertPoint(newBlock("dead"));
  return nullptr;
}

} // namespace mbc::codegen::detail
