// Statement execution: assignments, GOTO, NC blocks (with the control flow
// the runtime asks for: calls, M99, M02/M30), G65 calls and DPRNT/BPRNT.
#include "interp/interpreter.h"
#include <mbc/limits.h>

namespace mbc {

namespace {

unsigned char wordKind(WordKind k) {
  switch (k) {
    case WordKind::IntLiteral:
      return MBRT_WORD_INT_LITERAL;
    case WordKind::DecLiteral:
      return MBRT_WORD_DEC_LITERAL;
    case WordKind::Value:
      break;
  }
  return MBRT_WORD_VALUE;
}

} // namespace

mbrt_status Interpreter::execAssign(const Stmt& s) {
  Num v;
  if (mbrt_status st = eval(*s.value, v)) {
    return st;
  }
  // Only a plain reference copies vacancy (spec §2.3b).
  if (!s.value->isBareVariable()) {
    v = numeric(v);
  }
  double number = s.target.number;
  if (s.target.index) {
    Num idx;
    if (mbrt_status st = eval(*s.target.index, idx)) {
      return st;
    }
    number = numeric(idx);
  }
  if (mbrt_tracing(ctx_)) {
    trace(s, s.target.index ? std::initializer_list<mbrt_num>{number, v}
                            : std::initializer_list<mbrt_num>{v});
  }
  return mbrt_write_var(ctx_, number, v,
                        s.message.empty() ? nullptr : s.message.c_str());
}

mbrt_status Interpreter::execGoto(const Stmt& s) {
  if (s.gotoBlock) {
    if (mbrt_tracing(ctx_) && s.kind == StmtKind::Goto) {
      trace(s, {});
    }
    pc_ = *s.gotoBlock;
    return 0;
  }
  Num target;
  if (mbrt_status st = eval(*s.value, target)) {
    return st;
  }
  double n = roundHalfAway(numeric(target));
  if (mbrt_tracing(ctx_) && s.kind == StmtKind::Goto) {
    trace(s, {n});
  }
  if (!isSequenceNumber(n)) {
    return mbrt_raise_sequence(ctx_, "GOTO ", numeric(target),
                               unit_.programs[prog_].name.c_str());
  }
  return jumpTo(static_cast<int>(n), pc_);
}

// A word whose value is a bare vacant variable is dropped, address letter
// and all (spec §2.3a); any other value reads vacant as 0.
mbrt_status Interpreter::evalWords(const std::vector<Word>& words,
                                   std::vector<mbrt_word>& out) {
  out.clear();
  for (const Word& w : words) {
    Num v;
    if (w.bareVariable) {
      const Expr* ref = w.value.get();
      bool negative = ref->kind == ExprKind::Neg;
      if (negative) {
        ref = ref->args[0].get();
      }
      if (mbrt_status st = eval(*ref, v, w.letter)) {
        return st;
      }
      if (isVacant(v)) {
        continue;
      }
      if (negative) {
        v = negate(v);
      }
    } else if (mbrt_status st = eval(*w.value, v, w.letter)) {
      return st;
    }
    out.push_back({w.letter, wordKind(w.kind), numeric(v)});
  }
  return 0;
}

mbrt_status Interpreter::execNc(const Stmt& s, bool& finished) {
  if (mbrt_status st = evalWords(s.words, scratch_)) {
    return st;
  }
  mbrt_flow flow{};
  if (mbrt_status st =
          mbrt_nc_block(ctx_, scratch_.data(), scratch_.size(), &flow)) {
    return st;
  }
  switch (flow.kind) {
    case MBRT_FLOW_CALL: {
      int target = findProgram(flow.program);
      if (target < 0) {
        return mbrt_raise_program_not_found(ctx_, flow.program);
      }
      if (flow.repeat <= 0) {
        ++pc_;
        return 0;
      }
      return enter(target, flow.call_kind,
                   {flow.args, flow.args + flow.arg_count}, flow.repeat,
                   flow.start_seq);
    }
    case MBRT_FLOW_RETURN: {
      if (stack_.empty() && flow.has_seq != 0) {
        // M99 P in the main program jumps to that N of it (spec §5.8).
        return jumpToSeq(flow.seq, pc_);
      }
      if (stack_.empty()) {
        // M99 in the main program ends a batch run (spec Part A).
        mbrt_finish(ctx_, MBRT_END_MAIN_M99);
        finished = true;
        return 0;
      }
      return leave(flow.has_seq != 0, flow.seq, finished);
    }
    case MBRT_FLOW_END:
      mbrt_finish(ctx_, flow.counts_part ? MBRT_END_M02_M30 : MBRT_END_PROGRAM);
      finished = true;
      return 0;
    default:
      ++pc_;
      return 0;
  }
}

mbrt_status Interpreter::execMacroCall(const Stmt& s) {
  Num p;
  if (mbrt_status st = eval(*s.program, p)) {
    return st;
  }
  Num l = 1;
  if (s.repeat) {
    if (mbrt_status st = eval(*s.repeat, l)) {
      return st;
    }
  }
  std::vector<mbrt_word> args;
  if (mbrt_status st = evalWords(s.words, args)) {
    return st;
  }
  mbrt_trace_call(ctx_, p, l, args.data(), args.size());
  int target = findProgram(numeric(p));
  if (target < 0) {
    return mbrt_raise_program_not_found(ctx_, numeric(p));
  }
  auto repeat = static_cast<long>(roundHalfAway(numeric(l)));
  if (repeat <= 0) {
    ++pc_;
    return 0;
  }
  return enter(target, MBRT_CALL_MACRO, std::move(args), repeat);
}

mbrt_status Interpreter::execPrint(const Stmt& s) {
  std::vector<mbrt_print_item> items;
  items.reserve(s.items.size());
  for (const PrintItem& it : s.items) {
    mbrt_print_item out{nullptr, 0, it.intDigits, it.fracDigits};
    if (it.value) {
      if (mbrt_status st = eval(*it.value, out.value)) {
        return st;
      }
    } else {
      out.text = it.text.c_str();
    }
    items.push_back(out);
  }
  return s.kind == StmtKind::Dprnt
             ? mbrt_dprnt(ctx_, items.data(), items.size())
             : mbrt_bprnt(ctx_, items.data(), items.size());
}

} // namespace mbc
