// Internals of the IR evaluator (evaluator.h), shared by evaluator.cpp
// (activations, terminators, calls) and evaluator_ops.cpp (the other
// instructions). Not part of the library's interface.
#pragma once

#include "ir/evaluator.h"
#include <mbc/arith.h>
#include <mbc/compiled.h>

#include <memory>
#include <unordered_map>
#include <vector>

namespace mbc::ir::detail {

/// Internal status: the run ended normally (mbrt_finish was called); every
/// activation unwinds and evaluate() returns 0. Alarms are > 0.
inline constexpr mbrt_status kStop = MBRT_STOP;

/// A flow value: the record of an NC block, or the outcome of a call
/// (fromCall: flow.kind is NEXT, with has_seq/seq for the callee's M99 P).
struct FlowRec {
  mbrt_flow flow;
  bool fromCall;
};

/// The storage of one activation. Frames are kept per call depth and reused,
/// so a call allocates only the first time its depth is reached.
struct Frame {
  std::vector<double> values;  // by ValueId: numbers, bools as 0/1
  std::vector<FlowRec> flows;  // by ValueId: flow values
  std::vector<mbrt_word> args; // call.macro arguments, kept over the repeats
  bool hasSeq = false;         // how the activation left: M99 P seq
  double seq = 0;
  double retSeq = 0; // the N an M99 P into this activation asked for
};

class Evaluator {
public:
  Evaluator(const Module& module, mbrt_ctx* ctx);

  mbrt_status run(int mainIndex);

private:
  static constexpr BlockId kLeave = 0xffffffffU;  // the activation ends
  static constexpr BlockId kNoNext = 0xfffffffeU; // no terminator ran yet

  // Control (evaluator.cpp).
  mbrt_status runFunction(int index, int depth);
  Frame& frameAt(int depth, const Function& fn);
  mbrt_status enterPhis(const Function& fn, Frame& frame, const Block& block,
                        BlockId pred, std::size_t& first);
  mbrt_status resume(const Function& fn, Frame& frame, int depth,
                     const Inst& inst, BlockId& next);
  mbrt_status resumeNc(const Function& fn, Frame& frame, int depth,
                       const Inst& inst, BlockId& next);
  mbrt_status switchTo(const Function& fn, const Inst& inst, double value,
                       const char* jump, BlockId& next);
  mbrt_status startAt(const Function& fn, const Inst& inst, double seq,
                      BlockId& next);
  mbrt_status resumeAt(const Function& fn, Frame& frame, const Inst& inst,
                       double seq, BlockId& next);
  mbrt_status jumpToSeq(const Function& fn, const Inst& inst, double seq,
                        BlockId& next);
  mbrt_status caseTarget(const Function& fn, const Inst& inst, int seq,
                         BlockId& next);
  mbrt_status call(int callee, int depth, int kind, const mbrt_word* args,
                   std::size_t count, long repeat, double startSeq,
                   FlowRec& out);
  int findProgram(double number) const;
  mbrt_status internalError(const char* what);

  // Instructions (evaluator_ops.cpp).
  mbrt_status exec(const Function& fn, Frame& frame, int depth, ValueId id,
                   BlockId& next);
  mbrt_status execFn(const Inst& inst, const Frame& frame, double& out);
  mbrt_status execNc(const Inst& inst, Frame& frame, FlowRec& out);
  mbrt_status execCallMacro(const Inst& inst, Frame& frame, int depth,
                            FlowRec& out);
  mbrt_status execPrint(const Inst& inst, const Frame& frame);
  mbrt_status execTrace(const Inst& inst, const Frame& frame);
  mbrt_status buildWords(const Inst& inst, const Frame& frame,
                         std::vector<mbrt_word>& out);
  /// The string `ref` names; nullptr for none. message(): also for "".
  const char* text(StringRef ref) const;
  const char* message(StringRef ref) const;
  mbrt_status check(AlarmId id);

  const Module& module_;
  mbrt_ctx* ctx_;
  std::unordered_map<int, int> byNumber_;      // O number -> function index
  std::vector<std::unique_ptr<Frame>> frames_; // by call depth
  std::vector<mbrt_word> words_;               // nc words (no recursion)
  std::vector<mbrt_print_item> items_;         // dprnt/bprnt items
  std::vector<mbrt_num> traceValues_;          // trace values
  std::vector<double> phiValues_;              // parallel copy of phis
  std::vector<FlowRec> phiFlows_;
};

} // namespace mbc::ir::detail
