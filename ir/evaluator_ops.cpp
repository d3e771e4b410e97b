// The IR evaluator's instructions: values through the shared arithmetic
// (mbc/arith.h), variables, NC blocks, G65 calls, output and the
// terminators, with the runtime calls of interp/eval.cpp and
// interp/statements.cpp.
#include "ir/evaluator_impl.h"

#include <fmt/format.h>

namespace mbc::ir::detail {

namespace {

double truth(bool b) {
  return b ? 1.0 : 0.0;
}

mbrt_word word(char letter, int kind, double value) {
  return {letter, static_cast<unsigned char>(kind), value};
}

} // namespace

mbrt_status Evaluator::check(AlarmId id) {
  return id == AlarmId::None ? 0
                             : mbrt_raise(ctx_, static_cast<int>(id), nullptr);
}

// Every operation, in one switch over Op: -Wswitch names any op this engine
// does not know. A terminator sets `next`.
mbrt_status Evaluator::exec(const Function& fn, Frame& frame, int depth,
                            ValueId id, BlockId& next) {
  const Inst& inst = fn.insts[id];
  double* v = frame.values.data();
  switch (inst.op) {
    case Op::Const:
      v[id] = inst.get<Number>().value;
      return 0;
    case Op::Vacant:
      v[id] = vacant();
      return 0;
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
    case Op::BitAnd:
    case Op::BitOr:
    case Op::BitXor:
      return check(evalBinary(*binaryOf(inst.op), v[inst.ops[0]],
                              v[inst.ops[1]], &v[id]));
    case Op::Neg:
      v[id] = negate(v[inst.ops[0]]);
      return 0;
    case Op::ToNum:
      v[id] = numeric(v[inst.ops[0]]);
      return 0;
    case Op::Fn:
      return execFn(inst, frame, v[id]);
    case Op::Prm:
      return mbrt_read_parameter(
          ctx_, static_cast<int>(inst.get<Number>().value), v[inst.ops[0]],
          v[inst.ops[1]], v[inst.ops[2]], &v[id]);
    case Op::RoundAddr:
      return mbrt_round_address(ctx_, inst.get<AddressLetter>().letter,
                                v[inst.ops[0]], &v[id]);
    case Op::Eq:
    case Op::Ne:
    case Op::Gt:
    case Op::Ge:
    case Op::Lt:
    case Op::Le:
      v[id] = truth(
          evalCompare(*relationOf(inst.op), v[inst.ops[0]], v[inst.ops[1]]));
      return 0;
    case Op::LogAnd:
      v[id] = truth(v[inst.ops[0]] != 0 && v[inst.ops[1]] != 0);
      return 0;
    case Op::LogOr:
      v[id] = truth(v[inst.ops[0]] != 0 || v[inst.ops[1]] != 0);
      return 0;
    case Op::LogXor:
      v[id] = truth((v[inst.ops[0]] != 0) != (v[inst.ops[1]] != 0));
      return 0;
    case Op::Phi: // enterPhis assigns the phis at the head of a block
      return internalError("phi after the head of its block");
    case Op::RetSeq:
      v[id] = frame.retSeq;
      return 0;
    case Op::StartSeq:
      v[id] = mbrt_entry_sequence(ctx_);
      return 0;
    case Op::BlockSkip:
      v[id] = truth(mbrt_skip_switch(ctx_, inst.get<SkipSwitch>().number) != 0);
      return 0;
    case Op::LdVar:
      return mbrt_read_var(
          ctx_, static_cast<double>(inst.get<VarNumber>().number), &v[id]);
    case Op::StVar: {
      const VarNumber& var = inst.get<VarNumber>();
      return mbrt_write_var(ctx_, static_cast<double>(var.number),
                            v[inst.ops[0]], message(var.message));
    }
    case Op::LdInd:
      return mbrt_read_var(ctx_, numeric(v[inst.ops[0]]), &v[id]);
    case Op::StInd:
      return mbrt_write_var(ctx_, numeric(v[inst.ops[0]]), v[inst.ops[1]],
                            message(inst.get<Message>().text));
    case Op::Adp:
      return mbrt_adp(ctx_, numeric(v[inst.ops[0]]), &v[id]);
    case Op::Begin:
      return mbrt_begin_block(ctx_, fn.file.c_str(),
                              static_cast<int>(inst.get<SourceLine>().line));
    case Op::Nc:
      return execNc(inst, frame, frame.flows[id]);
    case Op::CallMacro:
      return execCallMacro(inst, frame, depth, frame.flows[id]);
    case Op::Dprnt:
    case Op::Bprnt:
      return execPrint(inst, frame);
    case Op::Popen:
      return mbrt_popen(ctx_);
    case Op::Pclos:
      return mbrt_pclos(ctx_);
    case Op::Trace:
      return execTrace(inst, frame);
    case Op::Br:
      next = inst.targets[0];
      return 0;
    case Op::CondBr:
      next = v[inst.ops[0]] != 0 ? inst.targets[0] : inst.targets[1];
      return 0;
    case Op::Switch: // a landing's switch words its alarm as M99 P does
      if (fn.insts[inst.ops[0]].op == Op::StartSeq) {
        return startAt(fn, inst, v[inst.ops[0]], next);
      }
      return switchTo(
          fn, inst, v[inst.ops[0]],
          fn.insts[inst.ops[0]].op == Op::RetSeq ? "M99 P" : "GOTO ", next);
    case Op::Resume:
      return resume(fn, frame, depth, inst, next);
    case Op::Ret:
      // The end of a called program's text returns like M99; the end of the
      // main program's text ends the run.
      if (depth == 0) {
        mbrt_finish(ctx_, MBRT_END_PROGRAM);
        return kStop;
      }
      next = kLeave;
      return 0;
    case Op::Raise:
      return mbrt_raise(ctx_, static_cast<int>(inst.get<AlarmRaise>().alarm),
                        text(inst.get<AlarmRaise>().detail));
    case Op::Unreachable:
      return internalError("unreachable code reached");
  }
  return internalError("unknown operation"); // a value outside Op
}

mbrt_status Evaluator::execFn(const Inst& inst, const Frame& frame,
                              double& out) {
  Num args[2] = {0, 0};
  for (std::size_t i = 0; i < inst.ops.size() && i < 2; ++i) {
    args[i] = frame.values[inst.ops[i]];
  }
  return mbrt_builtin(ctx_, static_cast<int>(inst.get<BuiltinFn>().fn), args[0],
                      args[1], &out);
}

const char* Evaluator::text(StringRef ref) const {
  const std::string* s = module_.text(ref);
  return s != nullptr ? s->c_str() : nullptr;
}

const char* Evaluator::message(StringRef ref) const {
  const char* s = text(ref);
  return s == nullptr || *s == '\0' ? nullptr : s;
}

// The words of nc or call.macro (Words). A bare vacant variable drops its
// word (spec §2.3a); any other value reads vacant as 0.
mbrt_status Evaluator::buildWords(const Inst& inst, const Frame& frame,
                                  std::vector<mbrt_word>& out) {
  out.clear();
  const std::vector<AddressWord>& words = inst.get<Words>().words;
  const std::size_t first = firstWordOperand(inst.op);
  if (first + words.size() != inst.ops.size()) {
    return internalError("words do not match the operands");
  }
  for (std::size_t k = 0; k < words.size(); ++k) {
    const char letter = words[k].letter;
    Num v = frame.values[inst.ops[first + k]];
    switch (words[k].kind) {
      case WordKind::Int:
        out.push_back(word(letter, MBRT_WORD_INT_LITERAL, numeric(v)));
        break;
      case WordKind::Dec:
        out.push_back(word(letter, MBRT_WORD_DEC_LITERAL, numeric(v)));
        break;
      case WordKind::Val:
        out.push_back(word(letter, MBRT_WORD_VALUE, numeric(v)));
        break;
      case WordKind::Var:
      case WordKind::NegVar:
        if (!isVacant(v)) {
          bool negated = words[k].kind == WordKind::NegVar;
          out.push_back(word(letter, MBRT_WORD_VALUE, negated ? negate(v) : v));
        }
        break;
    }
  }
  return 0;
}

mbrt_status Evaluator::execNc(const Inst& inst, Frame& frame, FlowRec& out) {
  if (mbrt_status st = buildWords(inst, frame, words_)) {
    return st;
  }
  out = FlowRec{};
  return mbrt_nc_block(ctx_, words_.data(), words_.size(), &out.flow);
}

// G65 (interp execMacroCall): P and L are operands 0 and 1.
mbrt_status Evaluator::execCallMacro(const Inst& inst, Frame& frame, int depth,
                                     FlowRec& out) {
  if (inst.ops.size() < 2) {
    return internalError("call.macro without P and L");
  }
  Num p = numeric(frame.values[inst.ops[0]]);
  Num l = numeric(frame.values[inst.ops[1]]);
  if (mbrt_status st = buildWords(inst, frame, frame.args)) {
    return st;
  }
  mbrt_trace_call(ctx_, p, l, frame.args.data(), frame.args.size());
  int target = findProgram(p);
  if (target < 0) {
    return mbrt_raise_program_not_found(ctx_, p);
  }
  auto repeat = static_cast<long>(roundHalfAway(l));
  out = FlowRec{};
  out.fromCall = true;
  if (repeat <= 0) {
    return 0;
  }
  return call(target, depth, MBRT_CALL_MACRO, frame.args.data(),
              frame.args.size(), repeat, 0.0, out);
}

mbrt_status Evaluator::execTrace(const Inst& inst, const Frame& frame) {
  const char* tmpl = message(inst.get<Message>().text);
  if (tmpl == nullptr) {
    return internalError("trace without a template");
  }
  traceValues_.clear();
  for (ValueId v : inst.ops) {
    traceValues_.push_back(frame.values[v]);
  }
  mbrt_trace_values(ctx_, tmpl, traceValues_.data(), traceValues_.size());
  return 0;
}

mbrt_status Evaluator::execPrint(const Inst& inst, const Frame& frame) {
  items_.clear();
  std::size_t next = 0;
  for (const PrintItem& item : inst.get<PrintItems>().items) {
    if (item.isValue()) {
      if (next >= inst.ops.size()) {
        return internalError("print item without a value");
      }
      items_.push_back({nullptr, frame.values[inst.ops[next++]], item.intDigits,
                        item.fracDigits});
      continue;
    }
    const char* s = text(item.text);
    if (s == nullptr) {
      return internalError("print text out of range");
    }
    items_.push_back({s, 0, 0, 0});
  }
  return inst.op == Op::Dprnt ? mbrt_dprnt(ctx_, items_.data(), items_.size())
                              : mbrt_bprnt(ctx_, items_.data(), items_.size());
}

} // namespace mbc::ir::detail
