// The IR evaluator's control: activations, phis, transfers, calls (G65,
// M98) and returns (M99 [P], the end of a called program's text), mirroring
// interp/interpreter.cpp and interp/statements.cpp effect for effect.
#include "ir/evaluator.h"

#include "ir/evaluator_impl.h"
#include <mbc/addresses.h>

#include <fmt/format.h>

namespace mbc::ir {

namespace detail {

Evaluator::Evaluator(const Module& module, mbrt_ctx* ctx)
    : module_(module), ctx_(ctx) {
  for (int i = 0; i < static_cast<int>(module.functions.size()); ++i) {
    if (module.functions[i].number >= 0) {
      byNumber_.emplace(module.functions[i].number, i);
    }
  }
}

mbrt_status Evaluator::run(int mainIndex) {
  if (mainIndex < 0 ||
      mainIndex >= static_cast<int>(module_.functions.size())) {
    return internalError("no main function");
  }
  mbrt_status st = runFunction(mainIndex, 0);
  return st > 0 ? st : 0;
}

int Evaluator::findProgram(double number) const {
  const std::optional<int> n = calledProgramNumber(number);
  const auto it = n ? byNumber_.find(*n) : byNumber_.end();
  return it == byNumber_.end() ? -1 : it->second;
}

mbrt_status Evaluator::internalError(const char* what) {
  return mbrt_raise(ctx_, static_cast<int>(AlarmId::InternalError),
                    fmt::format("IR evaluator: {}", what).c_str());
}

Frame& Evaluator::frameAt(int depth, const Function& fn) {
  while (frames_.size() <= static_cast<std::size_t>(depth)) {
    frames_.push_back(std::make_unique<Frame>());
  }
  Frame& frame = *frames_[static_cast<std::size_t>(depth)];
  if (frame.values.size() < fn.insts.size()) {
    frame.values.resize(fn.insts.size());
    frame.flows.resize(fn.insts.size());
  }
  frame.hasSeq = false;
  frame.seq = 0;
  return frame;
}

// Runs one activation. 0: it left normally (frame.hasSeq/seq tell whether
// by M99 P); kStop: the run ended; otherwise the alarm.
mbrt_status Evaluator::runFunction(int index, int depth) {
  const Function& fn = module_.functions[static_cast<std::size_t>(index)];
  Frame& frame = frameAt(depth, fn);
  BlockId block = 0;
  BlockId pred = kLeave;
  for (;;) {
    if (block >= fn.blocks.size() || fn.blocks[block].insts.empty()) {
      return internalError("branch to a missing or empty block");
    }
    const Block& b = fn.blocks[block];
    std::size_t i = 0;
    if (fn.insts[b.insts[0]].op == Op::Phi) {
      if (mbrt_status st = enterPhis(fn, frame, b, pred, i)) {
        return st;
      }
    }
    const std::size_t last = b.insts.size() - 1;
    BlockId next = kNoNext;
    for (; i <= last; ++i) {
      if (mbrt_status st = exec(fn, frame, depth, b.insts[i], next)) {
        return st;
      }
      if (next != kNoNext && i != last) {
        return internalError("terminator in the middle of a block");
      }
    }
    if (next == kNoNext) {
      return internalError("block without a terminator");
    }
    if (next == kLeave) {
      return 0;
    }
    pred = block;
    block = next;
  }
}

// The phis at the head of a block read their inputs for `pred` first and
// are assigned afterwards (parallel copy). `first` is set to the first
// instruction after them.
mbrt_status Evaluator::enterPhis(const Function& fn, Frame& frame,
                                 const Block& block, BlockId pred,
                                 std::size_t& first) {
  first = 0;
  phiValues_.clear();
  phiFlows_.clear();
  for (;
       first < block.insts.size() && fn.insts[block.insts[first]].op == Op::Phi;
       ++first) {
    const Inst& phi = fn.insts[block.insts[first]];
    std::size_t k = 0;
    while (k < phi.targets.size() && phi.targets[k] != pred) {
      ++k;
    }
    if (k >= phi.targets.size() || k >= phi.ops.size()) {
      return internalError("phi without an input for its predecessor");
    }
    if (phi.type == Type::Flow) {
      phiFlows_.push_back(frame.flows[phi.ops[k]]);
    } else {
      phiValues_.push_back(frame.values[phi.ops[k]]);
    }
  }
  std::size_t nv = 0;
  std::size_t nf = 0;
  for (std::size_t i = 0; i < first; ++i) {
    ValueId id = block.insts[i];
    if (fn.insts[id].type == Type::Flow) {
      frame.flows[id] = phiFlows_[nf++];
    } else {
      frame.values[id] = phiValues_[nv++];
    }
  }
  return 0;
}

// Computed GOTO (interp execGoto/jumpTo), and a landing's M99 P.
mbrt_status Evaluator::switchTo(const Function& fn, const Inst& inst,
                                double value, const char* jump, BlockId& next) {
  double target = numeric(value);
  double n = roundHalfAway(target);
  if (!isSequenceNumber(n)) {
    return mbrt_raise_sequence(ctx_, jump, target, fn.name.c_str());
  }
  return caseTarget(fn, inst, static_cast<int>(n), next);
}

// M98 Q: the N the program starts at, searched from its top (interp
// enter).
mbrt_status Evaluator::startAt(const Function& fn, const Inst& inst, double seq,
                               BlockId& next) {
  const std::vector<std::int64_t>& numbers = inst.get<SequenceCases>().numbers;
  for (std::size_t i = 0; i < numbers.size() && i < inst.targets.size(); ++i) {
    if (static_cast<double>(numbers[i]) == seq) {
      next = inst.targets[i];
      return 0;
    }
  }
  return mbrt_raise_start_sequence(ctx_, seq, fn.name.c_str());
}

// M99 P back into this activation: to the landing, or through the
// resume's own case table.
mbrt_status Evaluator::resumeAt(const Function& fn, Frame& frame,
                                const Inst& inst, double seq, BlockId& next) {
  if (inst.get<SequenceCases>().landing) {
    frame.retSeq = seq;
    next = inst.targets[1];
    return 0;
  }
  return jumpToSeq(fn, inst, seq, next);
}

// M99 P from a callee: resume at that N of this function (interp leave).
mbrt_status Evaluator::jumpToSeq(const Function& fn, const Inst& inst,
                                 double seq, BlockId& next) {
  double n = roundHalfAway(seq);
  if (!isSequenceNumber(n)) {
    return mbrt_raise_sequence(ctx_, "M99 P", seq, fn.name.c_str());
  }
  return caseTarget(fn, inst, static_cast<int>(n), next);
}

// The case for sequence number `seq` (SequenceCases).
mbrt_status Evaluator::caseTarget(const Function& fn, const Inst& inst, int seq,
                                  BlockId& next) {
  const std::vector<std::int64_t>& numbers = inst.get<SequenceCases>().numbers;
  const std::size_t first = firstCaseTarget(inst.op);
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    if (numbers[i] == seq && i + first < inst.targets.size()) {
      next = inst.targets[i + first];
      return 0;
    }
  }
  return mbrt_raise_sequence(ctx_, "", seq, fn.name.c_str());
}

mbrt_status Evaluator::resume(const Function& fn, Frame& frame, int depth,
                              const Inst& inst, BlockId& next) {
  const FlowRec& rec = frame.flows[inst.ops[0]];
  if (!rec.fromCall) {
    return resumeNc(fn, frame, depth, inst, next);
  }
  if (rec.flow.has_seq) {
    return resumeAt(fn, frame, inst, rec.flow.seq, next);
  }
  next = inst.targets[0];
  return 0;
}

// The flow of an NC block (interp execNc).
mbrt_status Evaluator::resumeNc(const Function& fn, Frame& frame, int depth,
                                const Inst& inst, BlockId& next) {
  const mbrt_flow flow = frame.flows[inst.ops[0]].flow;
  switch (flow.kind) {
    case MBRT_FLOW_CALL: {
      int target = findProgram(flow.program);
      if (target < 0) {
        return mbrt_raise_program_not_found(ctx_, flow.program);
      }
      FlowRec out{};
      if (mbrt_status st =
              call(target, depth, flow.call_kind, flow.args, flow.arg_count,
                   flow.repeat, flow.start_seq, out)) {
        return st;
      }
      if (out.flow.has_seq) {
        return resumeAt(fn, frame, inst, out.flow.seq, next);
      }
      next = inst.targets[0];
      return 0;
    }
    case MBRT_FLOW_RETURN:
      if (depth == 0 && flow.has_seq != 0) {
        // M99 P in the main program jumps to that N of it (spec §5.8).
        return resumeAt(fn, frame, inst, flow.seq, next);
      }
      if (depth == 0) {
        // M99 in the main program ends a batch run (spec Part A).
        mbrt_finish(ctx_, MBRT_END_MAIN_M99);
        return kStop;
      }
      frame.hasSeq = flow.has_seq != 0;
      frame.seq = flow.seq;
      next = kLeave;
      return 0;
    case MBRT_FLOW_END:
      mbrt_finish(ctx_, flow.counts_part ? MBRT_END_M02_M30 : MBRT_END_PROGRAM);
      return kStop;
    default:
      next = inst.targets[0];
      return 0;
  }
}

// A call of function `callee` (G65 with a new local level, or M98 on the
// same one) through the runtime, which repeats it and returns like every
// other engine. `out` is the call's flow: NEXT, with has_seq/seq for M99 P.
mbrt_status Evaluator::call(int callee, int depth, int kind,
                            const mbrt_word* args, std::size_t count,
                            long repeat, double startSeq, FlowRec& out) {
  struct Activation {
    Evaluator* self;
    int callee;
    int depth;
  };

  auto body = [](mbrt_ctx*, void* user, mbrt_flow* leave) -> mbrt_status {
    auto* a = static_cast<Activation*>(user);
    if (mbrt_status st = a->self->runFunction(a->callee, a->depth)) {
      return st;
    }
    const Frame& done = *a->self->frames_[static_cast<std::size_t>(a->depth)];
    leave->has_seq = done.hasSeq ? 1 : 0;
    leave->seq = done.seq;
    return 0;
  };
  Activation activation{this, callee, depth + 1};
  out = FlowRec{};
  out.fromCall = true;
  return mbrt_run_call(
      ctx_, module_.functions[static_cast<std::size_t>(callee)].name.c_str(),
      kind, args, count, repeat, startSeq, body, &activation, &out.flow);
}

} // namespace detail

mbrt_status evaluate(const Module& module, int mainIndex, mbrt_ctx* ctx) {
  detail::Evaluator evaluator(module, ctx);
  return evaluator.run(mainIndex);
}

} // namespace mbc::ir
