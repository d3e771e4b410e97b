// The IR evaluator's instructions other than terminators: values through the
// shared arithmetic (mbc/arith.h), variables, NC blocks, G65 calls and
// output, with the runtime calls of interp/eval.cpp and interp/statements.cpp.
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

// The frequent operations are handled here in one switch; the others by
// execValue, execVariable and execEffect.
mbrt_status Evaluator::exec(const Function& fn, Frame& frame, int depth,
                            ValueId id) {
  const Inst& inst = fn.insts[id];
  double* v = frame.values.data();
  switch (inst.op) {
    case Op::Const:
      v[id] = inst.imm;
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
    case Op::Eq:
    case Op::Ne:
    case Op::Gt:
    case Op::Ge:
    case Op::Lt:
    case Op::Le:
      v[id] = truth(
          evalCompare(*relationOf(inst.op), v[inst.ops[0]], v[inst.ops[1]]));
      return 0;
    case Op::LdVar:
      return mbrt_read_var(ctx_, static_cast<double>(inst.attr), &v[id]);
    case Op::StVar:
      return mbrt_write_var(ctx_, static_cast<double>(inst.attr),
                            v[inst.ops[0]], message(inst));
    case Op::Begin:
      return mbrt_begin_block(ctx_, fn.file.c_str(),
                              static_cast<int>(inst.attr));
    default:
      break;
  }
  switch (opInfo(inst.op).cls) {
    case OpClass::Value:
      return execValue(inst, frame, id);
    case OpClass::Variable:
      return execVariable(inst, frame, id);
    case OpClass::Effect:
    case OpClass::Control:
      return execEffect(inst, frame, depth, id);
  }
  return internalError(opInfo(inst.op).mnemonic);
}

mbrt_status Evaluator::execValue(const Inst& inst, Frame& frame, ValueId id) {
  std::vector<double>& v = frame.values;
  switch (inst.op) {
    case Op::Vacant:
      v[id] = vacant();
      return 0;
    case Op::Neg:
      v[id] = negate(v[inst.ops[0]]);
      return 0;
    case Op::ToNum:
      v[id] = numeric(v[inst.ops[0]]);
      return 0;
    case Op::Fn:
      return execFn(inst, frame, v[id]);
    case Op::RoundAddr:
      return mbrt_round_address(ctx_, static_cast<int>(inst.attr),
                                v[inst.ops[0]], &v[id]);
    default:
      return execLogic(inst, frame, id);
  }
}

mbrt_status Evaluator::execLogic(const Inst& inst, Frame& frame, ValueId id) {
  std::vector<double>& v = frame.values;
  switch (inst.op) {
    case Op::LogAnd:
      v[id] = truth(v[inst.ops[0]] != 0 && v[inst.ops[1]] != 0);
      return 0;
    case Op::LogOr:
      v[id] = truth(v[inst.ops[0]] != 0 || v[inst.ops[1]] != 0);
      return 0;
    case Op::LogXor:
      v[id] = truth((v[inst.ops[0]] != 0) != (v[inst.ops[1]] != 0));
      return 0;
    case Op::RetSeq:
      v[id] = frame.retSeq;
      return 0;
    case Op::BlockSkip:
      v[id] = truth(mbrt_skip_switch(ctx_, static_cast<int>(inst.attr)) != 0);
      return 0;
    default: // a phi after the head of its block
      return internalError("phi after the head of its block");
  }
}

mbrt_status Evaluator::execFn(const Inst& inst, const Frame& frame,
                              double& out) {
  Num args[2] = {0, 0};
  for (std::size_t i = 0; i < inst.ops.size() && i < 2; ++i) {
    args[i] = frame.values[inst.ops[i]];
  }
  return mbrt_builtin(ctx_, static_cast<int>(inst.attr), args[0], args[1],
                      &out);
}

const char* Evaluator::message(const Inst& inst) const {
  if (inst.str == 0 || inst.str > module_.strings.size()) {
    return nullptr;
  }
  const std::string& s = module_.strings[inst.str - 1];
  return s.empty() ? nullptr : s.c_str();
}

mbrt_status Evaluator::execVariable(const Inst& inst, Frame& frame,
                                    ValueId id) {
  std::vector<double>& v = frame.values;
  switch (inst.op) {
    case Op::LdInd:
      return mbrt_read_var(ctx_, numeric(v[inst.ops[0]]), &v[id]);
    case Op::StInd:
      return mbrt_write_var(ctx_, numeric(v[inst.ops[0]]), v[inst.ops[1]],
                            message(inst));
    case Op::Adp:
      return mbrt_adp(ctx_, numeric(v[inst.ops[0]]), &v[id]);
    default:
      return internalError("unexpected variable operation");
  }
}

mbrt_status Evaluator::execEffect(const Inst& inst, Frame& frame, int depth,
                                  ValueId id) {
  switch (inst.op) {
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
    default:
      return internalError("terminator in the middle of a block");
  }
}

// The words of nc (first = 0) or call.macro (first = 2: after P and L). A
// bare vacant variable drops its word (spec §2.3a); any other value reads
// vacant as 0. cases holds one descriptor per operand or per word operand.
mbrt_status Evaluator::buildWords(const Inst& inst, const Frame& frame,
                                  std::size_t first,
                                  std::vector<mbrt_word>& out) {
  out.clear();
  std::size_t skip = inst.cases.size() == inst.ops.size() ? 0 : first;
  if (inst.cases.size() + skip != inst.ops.size()) {
    return internalError("word descriptors do not match the operands");
  }
  for (std::size_t k = first; k < inst.ops.size(); ++k) {
    std::int64_t desc = inst.cases[k - skip];
    char letter = wordLetter(desc);
    Num v = frame.values[inst.ops[k]];
    switch (wordKind(desc)) {
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
          bool negated = wordKind(desc) == WordKind::NegVar;
          out.push_back(word(letter, MBRT_WORD_VALUE, negated ? negate(v) : v));
        }
        break;
    }
  }
  return 0;
}

mbrt_status Evaluator::execNc(const Inst& inst, Frame& frame, FlowRec& out) {
  if (mbrt_status st = buildWords(inst, frame, 0, words_)) {
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
  if (mbrt_status st = buildWords(inst, frame, 2, frame.args)) {
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
              frame.args.size(), repeat, out);
}

mbrt_status Evaluator::execTrace(const Inst& inst, const Frame& frame) {
  const char* tmpl = message(inst);
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

// Items: a text item is str << 1 (str indexes Module::strings), a value
// item (c * 10 + d) << 1 | 1 and takes the next operand.
mbrt_status Evaluator::execPrint(const Inst& inst, const Frame& frame) {
  items_.clear();
  std::size_t next = 0;
  for (std::int64_t item : inst.cases) {
    if (item & 1) {
      if (next >= inst.ops.size()) {
        return internalError("print item without a value");
      }
      int format = static_cast<int>(item >> 1);
      items_.push_back(
          {nullptr, frame.values[inst.ops[next++]], format / 10, format % 10});
      continue;
    }
    auto str = static_cast<std::size_t>(item >> 1);
    if (str >= module_.strings.size()) {
      return internalError("print text out of range");
    }
    items_.push_back({module_.strings[str].c_str(), 0, 0, 0});
  }
  return inst.op == Op::Dprnt ? mbrt_dprnt(ctx_, items_.data(), items_.size())
                              : mbrt_bprnt(ctx_, items_.data(), items_.size());
}

} // namespace mbc::ir::detail
