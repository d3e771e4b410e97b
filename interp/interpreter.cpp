// The interpreter's control loop: blocks, GOTO search, WHILE/END, calls and
// returns (G65/M98/M99), and the end of the run.
#include "interp/interpreter.h"

#include <mbc/addresses.h>

#include <cmath>

namespace mbc {

Interpreter::Interpreter(const Unit& unit, const SourceManager& sources,
                         mbrt_ctx* ctx)
    : unit_(unit), sources_(sources), ctx_(ctx) {
  for (int i = 0; i < static_cast<int>(unit.programs.size()); ++i) {
    if (unit.programs[i].number >= 0) {
      byNumber_.emplace(unit.programs[i].number, i);
    }
  }
}

int Interpreter::findProgram(double number) const {
  const std::optional<int> n = calledProgramNumber(number);
  const auto it = n ? byNumber_.find(*n) : byNumber_.end();
  return it == byNumber_.end() ? -1 : it->second;
}

mbrt_status Interpreter::run(int mainIndex) {
  prog_ = mainIndex;
  pc_ = 0;
  stack_.clear();
  for (;;) {
    const Program& p = unit_.programs[prog_];
    if (pc_ >= static_cast<int>(p.blocks.size())) {
      // The end of a called program's text returns like M99.
      bool finished = false;
      if (mbrt_status st = leave(false, 0, finished)) {
        return st;
      }
      if (finished) {
        mbrt_finish(ctx_, MBRT_END_PROGRAM);
        return 0;
      }
      continue;
    }
    const Block& b = p.blocks[pc_];
    if (b.skipLevel && mbrt_skip_switch(ctx_, b.skipLevel)) {
      ++pc_;
      continue;
    }
    if (mbrt_status st =
            mbrt_begin_block(ctx_, sources_.name(p.file).c_str(), b.line)) {
      return st;
    }
    if (b.alarm != AlarmId::None) {
      return mbrt_raise(ctx_, static_cast<int>(b.alarm), b.alarmDetail.c_str());
    }
    bool finished = false;
    mbrt_status st = 0;
    if (b.stmt.kind == StmtKind::Nc) {
      st = execNc(b.stmt, finished);
    } else {
      st = step(b);
    }
    if (st) {
      return st;
    }
    if (finished) {
      return 0;
    }
  }
}

mbrt_status Interpreter::step(const Block& b) {
  const Stmt& s = b.stmt;
  switch (s.kind) {
    case StmtKind::Empty:
      ++pc_;
      return 0;
    case StmtKind::Assign:
      ++pc_;
      return execAssign(s);
    case StmtKind::IfGoto:
    case StmtKind::IfThen: {
      bool taken = false;
      if (mbrt_status st = evalCond(*s.cond, taken)) {
        return st;
      }
      // A taken IF-THEN is traced with its assignment by execAssign.
      if (mbrt_tracing(ctx_) && !(taken && s.kind == StmtKind::IfThen)) {
        trace(s, {taken ? 1.0 : 0.0}, taken);
      }
      if (!taken) {
        ++pc_;
        return 0;
      }
      if (s.kind == StmtKind::IfThen) {
        ++pc_;
        return execAssign(s);
      }
      return execGoto(s);
    }
    case StmtKind::Goto:
      return execGoto(s);
    case StmtKind::While: {
      bool go = true;
      if (s.cond) {
        if (mbrt_status st = evalCond(*s.cond, go)) {
          return st;
        }
      }
      if (mbrt_tracing(ctx_)) {
        trace(s, {go ? 1.0 : 0.0});
      }
      pc_ = go ? pc_ + 1 : s.match + 1;
      return 0;
    }
    case StmtKind::End:
      if (mbrt_tracing(ctx_)) {
        trace(s, {});
      }
      pc_ = s.match;
      return 0;
    case StmtKind::MacroCall:
      return execMacroCall(s);
    case StmtKind::Dprnt:
    case StmtKind::Bprnt:
      ++pc_;
      return execPrint(s);
    case StmtKind::Popen:
    case StmtKind::Pclos:
      ++pc_;
      return s.kind == StmtKind::Popen ? mbrt_popen(ctx_) : mbrt_pclos(ctx_);
    case StmtKind::Nc:
      break;
  }
  return 0;
}

int Interpreter::findSequence(int program, int seq, int from) {
  if (sequences_.empty()) {
    sequences_.resize(unit_.programs.size());
  }
  std::optional<SequenceIndex>& index =
      sequences_[static_cast<std::size_t>(program)];
  if (!index) {
    index.emplace(unit_.programs[static_cast<std::size_t>(program)]);
  }
  return index->find(seq, from);
}

// Computed targets are searched like constant ones: forward from the jump,
// then from the top of the program (spec Part A); none is PS0128.
mbrt_status Interpreter::jumpTo(int seq, int from) {
  int target = findSequence(prog_, seq, from);
  if (target < 0) {
    return mbrt_raise_sequence(ctx_, "", seq,
                               unit_.programs[prog_].name.c_str());
  }
  pc_ = target;
  return 0;
}

mbrt_status Interpreter::enter(int program, int kind,
                               std::vector<mbrt_word> args, long repeat,
                               double startSeq) {
  const char* name = unit_.programs[program].name.c_str();
  if (mbrt_status st = mbrt_call(ctx_, name, kind, args.data(), args.size())) {
    return st;
  }
  stack_.push_back(
      {prog_, pc_ + 1, repeat - 1, kind, std::move(args), startSeq});
  prog_ = program;
  return start();
}

// The called program's first block, or the N an M98 Q names, searched from
// its top (PS0078 when it has none).
mbrt_status Interpreter::start() {
  const double seq = stack_.back().startSeq;
  pc_ = 0;
  if (seq == 0) {
    return 0;
  }
  const Program& program = unit_.programs[prog_];
  const int target = findSequence(prog_, static_cast<int>(seq), 0);
  if (target < 0) {
    return mbrt_raise_start_sequence(ctx_, seq, program.name.c_str());
  }
  pc_ = target;
  return 0;
}

// M99 (or the end of a called program): repeat the call while L allows,
// else resume the caller after the calling block or at M99 P's N.
mbrt_status Interpreter::leave(bool hasSeq, double seq, bool& finished) {
  if (stack_.empty()) {
    finished = true;
    return 0;
  }
  mbrt_return(ctx_);
  Frame& f = stack_.back();
  if (f.remaining > 0 && !hasSeq) {
    --f.remaining;
    const char* name = unit_.programs[prog_].name.c_str();
    if (mbrt_status st =
            mbrt_call(ctx_, name, f.kind, f.args.data(), f.args.size())) {
      return st;
    }
    return start();
  }
  prog_ = f.program;
  pc_ = f.returnBlock;
  stack_.pop_back();
  if (!hasSeq) {
    return 0;
  }
  return jumpToSeq(seq, pc_ - 1);
}

mbrt_status Interpreter::jumpToSeq(double seq, int from) {
  double n = roundHalfAway(seq);
  if (!isSequenceNumber(n)) {
    return mbrt_raise_sequence(ctx_, "M99 P", seq,
                               unit_.programs[prog_].name.c_str());
  }
  return jumpTo(static_cast<int>(n), from);
}

} // namespace mbc
