// The reference interpreter: runs the AST block by block like a control does
// (no lookahead; spec Part A), calling the shared runtime for variables,
// motion and output. It is the semantic oracle every other engine is
// compared with.
#pragma once

#include "frontend/ast.h"
#include "frontend/sema.h"
#include "frontend/source.h"
#include <mbc/arith.h>
#include <mbc/compiled.h>
#include <mbc/engine.h>

#include <fmt/format.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mbc {

class Interpreter {
public:
  /// Machine settings (NAT, block skip) come from the context.
  Interpreter(const Unit& unit, const SourceManager& sources, mbrt_ctx* ctx);

  /// Runs programs[mainIndex] to its end (after the caller's mbrt_start).
  /// Returns 0 or the alarm that stopped the run (its report is in the
  /// context).
  mbrt_status run(int mainIndex);

private:
  struct Frame {
    int program;
    int returnBlock;
    long remaining; // repetitions still to run (L)
    int kind;       // mbrt_call_kind
    std::vector<mbrt_word> args;
    double startSeq; // M98 Q: the N each repetition starts at, 0: the top
  };

  // Control (interpreter.cpp).
  mbrt_status step(const Block& b);
  mbrt_status jumpTo(int seq, int from);
  // M99 P's `seq` rounded, PS0128 outside 1..99999.
  mbrt_status jumpToSeq(double seq, int from);
  mbrt_status enter(int program, int kind, std::vector<mbrt_word> args,
                    long repeat, double startSeq = 0);
  mbrt_status start();
  mbrt_status leave(bool hasSeq, double seq, bool& finished);
  int findProgram(double number) const;
  /// findSequence in a program, its labels indexed at its first search.
  int findSequence(int program, int seq, int from);

  // Statements (statements.cpp).
  mbrt_status execAssign(const Stmt& s);
  mbrt_status execGoto(const Stmt& s);
  mbrt_status execNc(const Stmt& s, bool& finished);
  mbrt_status execMacroCall(const Stmt& s);
  mbrt_status execPrint(const Stmt& s);
  mbrt_status evalWords(const std::vector<Word>& words,
                        std::vector<mbrt_word>& out);

  // Expressions (eval.cpp).
  mbrt_status eval(const Expr& e, Num& out, char roundLetter = 0);
  mbrt_status evalCond(const Expr& e, bool& out);
  mbrt_status evalCall(const Expr& e, Num& out, char roundLetter);
  mbrt_status check(AlarmId id);

  // The --trace line of a statement the interpreter runs itself
  // (frontend/trace_text.h); call only when mbrt_tracing.
  void trace(const Stmt& s, std::initializer_list<mbrt_num> values,
             bool taken = true);

  const Unit& unit_;
  const SourceManager& sources_;
  mbrt_ctx* ctx_;
  std::map<int, int> byNumber_; // O number -> program index
  std::vector<std::optional<SequenceIndex>> sequences_; // by program index
  int prog_ = 0;
  int pc_ = 0;
  std::vector<Frame> stack_;
  std::vector<mbrt_word> scratch_;
};

} // namespace mbc
