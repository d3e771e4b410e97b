// AST -> IR lowering (see lower.h). The control flow mirrors the reference
// interpreter block for block, so that both engines raise the same alarms at
// the same blocks: a source block's head is where GOTO, WHILE and END jump,
// and its `begin` counts it exactly once per execution.
#include "ir/lower.h"

#include "frontend/sema.h"
#include "frontend/trace_text.h"
#include <mbc/engine.h>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <set>

namespace mbc::ir {

namespace {

class FunctionLowering {
public:
  FunctionLowering(const Program& program, Module& module, Function& fn,
                   const LowerOptions& options, bool startsAtSequence,
                   bool returnsToSequence)
      : program_(program), module_(module), fn_(fn), options_(options),
        startsAtSequence_(startsAtSequence),
        returnsToSequence_(returnsToSequence), sequenceIndex_(program) {}

  void run();

private:
  BlockId newBlock();
  ValueId emit(Op op, std::vector<ValueId> ops = {});
  void terminate(Op op, std::vector<BlockId> targets,
                 std::vector<ValueId> ops = {});
  void lowerBlock(int index);
  void lowerStatement(const Stmt& s, int index);
  void lowerAssign(const Stmt& s);
  void trace(const Stmt& s, std::vector<ValueId> values, bool taken = true);
  void lowerGoto(const Stmt& s, int index);
  Words lowerWords(const std::vector<Word>& words, std::vector<ValueId>& ops);
  void lowerPrint(const Stmt& s);
  void resumeAfter(ValueId flow, int index);
  void addSequenceTable(SequenceCases& cases, std::vector<BlockId>& targets,
                        int from);
  BlockId landing(int from);
  void enterAt(BlockId entry);
  ValueId lowerExpr(const Expr& e, char roundLetter = 0);
  ValueId lowerNum(const Expr& e, char roundLetter = 0);
  ValueId lowerCall(const Expr& e, char roundLetter);
  ValueId constant(double v);

  BlockId head(int index) const { return heads_[index]; }

  const Program& program_;
  Module& module_;
  Function& fn_;
  const LowerOptions& options_;
  bool startsAtSequence_;      // some M98 Q may enter it (mayStartAtSequence)
  bool returnsToSequence_;     // some M99 P may return (mayReturnToSequence)
  std::vector<BlockId> heads_; // head block of each source block, + exit
  BlockId cur_ = 0;
  std::uint32_t line_ = 0;
  std::set<int> sequences_;       // every N of the program
  SequenceIndex sequenceIndex_;   // where a jump to each N lands
  bool repeatedSequence_ = false; // some N numbers two blocks
  // The M99 P landings: one per distinct table (one unless N numbers repeat).
  std::map<std::vector<BlockId>, BlockId> landings_;
};

BlockId FunctionLowering::newBlock() {
  fn_.blocks.emplace_back();
  return static_cast<BlockId>(fn_.blocks.size() - 1);
}

ValueId FunctionLowering::emit(Op op, std::vector<ValueId> ops) {
  Inst inst;
  inst.op = op;
  inst.type = opInfo(op).result;
  inst.block = cur_;
  inst.line = line_;
  inst.ops = std::move(ops);
  inst.data = payloadOf(op);
  auto id = static_cast<ValueId>(fn_.insts.size());
  fn_.insts.push_back(std::move(inst));
  fn_.blocks[cur_].insts.push_back(id);
  return id;
}

void FunctionLowering::terminate(Op op, std::vector<BlockId> targets,
                                 std::vector<ValueId> ops) {
  ValueId id = emit(op, std::move(ops));
  fn_.insts[id].targets = std::move(targets);
}

ValueId FunctionLowering::constant(double v) {
  ValueId id = emit(Op::Const);
  fn_.insts[id].get<Number>().value = v;
  return id;
}

void FunctionLowering::run() {
  auto n = static_cast<int>(program_.blocks.size());
  for (int i = 0; i < n; ++i) {
    int seq = program_.blocks[i].seq;
    if (seq >= 0 && !sequences_.insert(seq).second) {
      repeatedSequence_ = true;
    }
  }
  // The entry block has no predecessor, so that a GOTO to the first block
  // (and a phi there) has a block of its own.
  BlockId entry = newBlock();
  for (int i = 0; i <= n; ++i) {
    heads_.push_back(newBlock());
  }
  enterAt(entry);
  for (int i = 0; i < n; ++i) {
    lowerBlock(i);
  }
  // The end of the text: M99 for a called program, the end of the run for
  // the main program (the evaluator knows which it is).
  cur_ = head(n);
  terminate(Op::Ret, {});
}

void FunctionLowering::lowerBlock(int index) {
  const mbc::Block& b = program_.blocks[index];
  cur_ = head(index);
  line_ = static_cast<std::uint32_t>(b.line);
  if (b.skipLevel) {
    ValueId on = emit(Op::BlockSkip);
    fn_.insts[on].data = SkipSwitch{b.skipLevel};
    BlockId body = newBlock();
    terminate(Op::CondBr, {head(index + 1), body}, {on});
    cur_ = body;
  }
  fn_.insts[emit(Op::Begin)].data = SourceLine{line_};
  if (b.alarm != AlarmId::None) {
    fn_.insts[emit(Op::Raise)].data =
        AlarmRaise{b.alarm, module_.intern(b.alarmDetail)};
    return;
  }
  lowerStatement(b.stmt, index);
}

void FunctionLowering::lowerStatement(const Stmt& s, int index) {
  BlockId next = head(index + 1);
  switch (s.kind) {
    case StmtKind::Empty:
      terminate(Op::Br, {next});
      return;
    case StmtKind::Assign:
      lowerAssign(s);
      terminate(Op::Br, {next});
      return;
    case StmtKind::IfGoto:
    case StmtKind::IfThen: {
      ValueId c = lowerExpr(*s.cond);
      BlockId taken = newBlock();
      BlockId notTaken = next;
      if (s.kind == StmtKind::IfGoto) {
        trace(s, {c});
      } else if (options_.trace) {
        notTaken = newBlock();
      }
      terminate(Op::CondBr, {taken, notTaken}, {c});
      if (notTaken != next) {
        cur_ = notTaken;
        trace(s, {}, false);
        terminate(Op::Br, {next});
      }
      cur_ = taken;
      if (s.kind == StmtKind::IfThen) {
        lowerAssign(s);
        terminate(Op::Br, {next});
      } else {
        lowerGoto(s, index);
      }
      return;
    }
    case StmtKind::Goto:
      if (s.gotoBlock) {
        trace(s, {});
      }
      lowerGoto(s, index);
      return;
    case StmtKind::While: {
      if (!s.cond) {
        trace(s, {});
        terminate(Op::Br, {next});
        return;
      }
      ValueId c = lowerExpr(*s.cond);
      trace(s, {c});
      terminate(Op::CondBr, {next, head(s.match + 1)}, {c});
      return;
    }
    case StmtKind::End:
      trace(s, {});
      terminate(Op::Br, {head(s.match)});
      return;
    case StmtKind::Nc: {
      std::vector<ValueId> ops;
      Words words = lowerWords(s.words, ops);
      ValueId f = emit(Op::Nc, std::move(ops));
      fn_.insts[f].data = std::move(words);
      resumeAfter(f, index);
      return;
    }
    case StmtKind::MacroCall: {
      std::vector<ValueId> ops{lowerExpr(*s.program),
                               s.repeat ? lowerExpr(*s.repeat) : constant(1)};
      Words words = lowerWords(s.words, ops);
      ValueId f = emit(Op::CallMacro, std::move(ops));
      fn_.insts[f].data = std::move(words);
      resumeAfter(f, index);
      return;
    }
    case StmtKind::Dprnt:
    case StmtKind::Bprnt:
      lowerPrint(s);
      terminate(Op::Br, {next});
      return;
    case StmtKind::Popen:
    case StmtKind::Pclos:
      emit(s.kind == StmtKind::Popen ? Op::Popen : Op::Pclos);
      terminate(Op::Br, {next});
      return;
  }
}

// The value is evaluated before the variable number, as in the interpreter.
void FunctionLowering::lowerAssign(const Stmt& s) {
  // Only a plain reference copies vacancy (spec §2.3b); a bracketed
  // reference or ADP of a vacant variable stores 0.
  ValueId v =
      s.value->isBareVariable() ? lowerExpr(*s.value) : lowerNum(*s.value);
  StringRef message = s.message.empty() ? 0 : module_.intern(s.message);
  if (s.target.index) {
    ValueId idx = lowerNum(*s.target.index);
    trace(s, {idx, v});
    fn_.insts[emit(Op::StInd, {idx, v})].data = Message{message};
  } else {
    trace(s, {v});
    fn_.insts[emit(Op::StVar, {v})].data = VarNumber{s.target.number, message};
  }
}

void FunctionLowering::trace(const Stmt& s, std::vector<ValueId> values,
                             bool taken) {
  if (options_.trace) {
    ValueId t = emit(Op::Trace, std::move(values));
    fn_.insts[t].data =
        Message{module_.intern(traceTemplate(program_, s, taken))};
  }
}

void FunctionLowering::lowerGoto(const Stmt& s, int index) {
  if (s.gotoBlock) {
    terminate(Op::Br, {head(*s.gotoBlock)});
    return;
  }
  ValueId target = lowerExpr(*s.value);
  if (s.kind == StmtKind::Goto) {
    trace(s, {target});
  }
  terminate(Op::Switch, {}, {target});
  Inst& sw = fn_.insts.back();
  addSequenceTable(sw.get<SequenceCases>(), sw.targets, index);
}

// Where each N sends a jump from block `from`. Only a repeated N makes the
// answer depend on `from` (the search goes forward from there).
void FunctionLowering::addSequenceTable(SequenceCases& cases,
                                        std::vector<BlockId>& targets,
                                        int from) {
  for (int seq : sequences_) {
    cases.numbers.push_back(seq);
    targets.push_back(head(sequenceIndex_.find(seq, from)));
  }
}

// A call or an NC block goes on with the next block, or, when the callee
// leaves by M99 P, at the landing that switches on the sequence number: one
// table per program rather than one per call keeps the IR linear in the
// number of calls and N numbers (and none when no M99 P is in the unit).
void FunctionLowering::resumeAfter(ValueId flow, int index) {
  std::vector<BlockId> targets{head(index + 1)};
  if (!sequences_.empty() && returnsToSequence_) {
    targets.push_back(landing(index));
  }
  bool landing = targets.size() == 2;
  terminate(Op::Resume, std::move(targets), {flow});
  fn_.insts.back().get<SequenceCases>().landing = landing;
}

BlockId FunctionLowering::landing(int from) {
  if (!repeatedSequence_ && !landings_.empty()) {
    return landings_.begin()->second; // the one table every resume shares
  }
  SequenceCases table;
  std::vector<BlockId> targets;
  addSequenceTable(table, targets, from);
  auto it = landings_.find(targets);
  if (it != landings_.end()) {
    return it->second;
  }
  BlockId saved = cur_;
  std::uint32_t savedLine = line_;
  BlockId land = newBlock();
  cur_ = land;
  ValueId seq = emit(Op::RetSeq);
  terminate(Op::Switch, {}, {seq});
  fn_.insts.back().data = std::move(table);
  fn_.insts.back().targets = targets;
  landings_.emplace(std::move(targets), land);
  cur_ = saved;
  line_ = savedLine;
  return land;
}

// A program starts at its first block, or at the N an M98 Q names,
// searched from its top (PS0078 when it has none).
void FunctionLowering::enterAt(BlockId entry) {
  cur_ = entry;
  if (!startsAtSequence_) {
    terminate(Op::Br, {head(0)});
    return;
  }
  ValueId start = emit(Op::StartSeq);
  ValueId top = emit(Op::Eq, {start, constant(0)});
  BlockId search = newBlock();
  terminate(Op::CondBr, {head(0), search}, {top});
  cur_ = search;
  terminate(Op::Switch, {}, {start});
  Inst& sw = fn_.insts.back();
  addSequenceTable(sw.get<SequenceCases>(), sw.targets, 0);
}

Words FunctionLowering::lowerWords(const std::vector<Word>& words,
                                   std::vector<ValueId>& ops) {
  Words into;
  for (const Word& w : words) {
    WordKind kind = WordKind::Val;
    ValueId v = 0;
    if (w.bareVariable) {
      bool negative = w.value->kind == ExprKind::Neg;
      kind = negative ? WordKind::NegVar : WordKind::Var;
      v = lowerExpr(negative ? *w.value->args[0] : *w.value, w.letter);
    } else if (w.kind == mbc::WordKind::IntLiteral ||
               w.kind == mbc::WordKind::DecLiteral) {
      kind =
          w.kind == mbc::WordKind::IntLiteral ? WordKind::Int : WordKind::Dec;
      v = constant(w.value->number);
    } else {
      v = lowerNum(*w.value, w.letter);
    }
    ops.push_back(v);
    into.words.push_back({w.letter, kind});
  }
  return into;
}

void FunctionLowering::lowerPrint(const Stmt& s) {
  std::vector<ValueId> ops;
  PrintItems items;
  for (const mbc::PrintItem& it : s.items) {
    if (it.value) {
      ops.push_back(lowerExpr(*it.value));
      items.items.push_back({0, static_cast<std::uint8_t>(it.intDigits),
                             static_cast<std::uint8_t>(it.fracDigits)});
    } else {
      items.items.push_back({module_.intern(it.text)});
    }
  }
  ValueId p =
      emit(s.kind == StmtKind::Dprnt ? Op::Dprnt : Op::Bprnt, std::move(ops));
  fn_.insts[p].data = std::move(items);
}

// roundLetter != 0: the expression is an NC address, where ROUND rounds to
// the address's least increment; it does not reach into #[...].
ValueId FunctionLowering::lowerExpr(const Expr& e, char roundLetter) {
  switch (e.kind) {
    case ExprKind::Number:
      return constant(e.number);
    case ExprKind::Var: {
      if (e.var == 0) {
        return emit(Op::Vacant); // #0 is always vacant and cannot alarm
      }
      ValueId v = emit(Op::LdVar);
      fn_.insts[v].get<VarNumber>().number = e.var;
      return v;
    }
    case ExprKind::Indirect:
      return emit(Op::LdInd, {lowerNum(*e.args[0])});
    case ExprKind::Neg:
      return emit(Op::Neg, {lowerNum(*e.args[0], roundLetter)});
    case ExprKind::Binary: {
      static constexpr Op kOps[] = {Op::Add, Op::Sub,    Op::Mul,   Op::Div,
                                    Op::Mod, Op::BitAnd, Op::BitOr, Op::BitXor};
      ValueId a = lowerNum(*e.args[0], roundLetter);
      ValueId b = lowerNum(*e.args[1], roundLetter);
      return emit(kOps[static_cast<int>(e.binOp)], {a, b});
    }
    case ExprKind::Compare: {
      static constexpr Op kOps[] = {Op::Eq, Op::Ne, Op::Gt,
                                    Op::Ge, Op::Lt, Op::Le};
      // EQ and NE tell a vacant bare reference from 0; the others, like
      // arithmetic, read vacant as 0 (spec §2.3).
      bool equality = e.relOp == RelOp::Eq || e.relOp == RelOp::Ne;
      auto operand = [&](const Expr& x) {
        return equality && x.isBareVariable() ? lowerExpr(x) : lowerNum(x);
      };
      ValueId a = operand(*e.args[0]);
      ValueId b = operand(*e.args[1]);
      return emit(kOps[static_cast<int>(e.relOp)], {a, b});
    }
    case ExprKind::Logical: {
      ValueId a = lowerExpr(*e.args[0]);
      ValueId b = lowerExpr(*e.args[1]);
      Op op = e.binOp == BinOp::And  ? Op::LogAnd
              : e.binOp == BinOp::Or ? Op::LogOr
                                     : Op::LogXor;
      return emit(op, {a, b});
    }
    case ExprKind::Call:
      return lowerCall(e, roundLetter);
    case ExprKind::Parameter: {
      const bool bit = (e.parameterForm & MBRT_PARAMETER_BIT) != 0;
      const bool axis = (e.parameterForm & MBRT_PARAMETER_AXIS) != 0;
      const ValueId n = lowerNum(*e.args[0]);
      const ValueId b = bit ? lowerNum(*e.args[1]) : constant(0);
      const ValueId a = axis ? lowerNum(*e.args.back()) : constant(0);
      const ValueId v = emit(Op::Prm, {n, b, a});
      fn_.insts[v].get<Number>().value = e.parameterForm;
      return v;
    }
  }
  return constant(0);
}

// An expression read as a number: vacant reads as 0.
ValueId FunctionLowering::lowerNum(const Expr& e, char roundLetter) {
  ValueId v = lowerExpr(e, roundLetter);
  return fn_.insts[v].type == Type::VNum ? emit(Op::ToNum, {v}) : v;
}

ValueId FunctionLowering::lowerCall(const Expr& e, char roundLetter) {
  const Expr& arg = *e.args[0];
  if (e.builtin == Builtin::Adp) {
    if (!arg.isBareVariable()) {
      return lowerNum(arg); // no macro argument: ADP is the identity
    }
    ValueId number =
        arg.kind == ExprKind::Var ? constant(arg.var) : lowerNum(*arg.args[0]);
    return emit(Op::Adp, {number});
  }
  std::vector<ValueId> ops;
  for (const ExprPtr& a : e.args) {
    ops.push_back(lowerNum(*a, roundLetter));
  }
  if (e.builtin == Builtin::Round && roundLetter) {
    ValueId v = emit(Op::RoundAddr, std::move(ops));
    fn_.insts[v].data = AddressLetter{roundLetter};
    return v;
  }
  ValueId v = emit(Op::Fn, std::move(ops));
  fn_.insts[v].data = BuiltinFn{e.builtin};
  return v;
}

bool isLiteral(const Word& w, double value) {
  return w.kind == mbc::WordKind::IntLiteral &&
         w.value->kind == ExprKind::Number && w.value->number == value;
}

// Whether some NC block of the unit has an M code that may be one of
// `codes` (an M code computed at run time may be any) and a word `letter`.
// Calls reach only the programs of their own unit, so the answer is exact.
bool someBlockMayBe(const Unit& unit, std::initializer_list<double> codes,
                    char letter) {
  const auto mayBe = [&](const Word& w) {
    return w.letter == 'M' &&
           (w.kind == mbc::WordKind::Value ||
            std::any_of(codes.begin(), codes.end(),
                        [&](double code) { return isLiteral(w, code); }));
  };
  const auto has = [&](const Word& w) { return w.letter == letter; };
  for (const Program& p : unit.programs) {
    for (const mbc::Block& b : p.blocks) {
      const std::vector<Word>& words = b.stmt.words;
      if (b.stmt.kind == StmtKind::Nc &&
          std::any_of(words.begin(), words.end(), has) &&
          std::any_of(words.begin(), words.end(), mayBe)) {
        return true;
      }
    }
  }
  return false;
}

// Only an M98 or M198 block with Q starts a program at a sequence number.
// Where the unit has none, no program needs the start's case table, whose
// edges into every N would cost the optimiser what it knows there.
bool mayStartAtSequence(const Unit& unit) {
  return someBlockMayBe(unit, {98, 198}, 'Q');
}

// Only an M99 P comes back at an N of its caller, or jumps to one in a
// main program. Where the unit has none, no call needs the landing, whose
// table per calling block grows with the blocks times the N numbers when
// N numbers repeat (CAM output that numbers each operation from N1).
bool mayReturnToSequence(const Unit& unit) {
  return someBlockMayBe(unit, {99}, 'P');
}

} // namespace

Module lower(const Unit& unit, const SourceManager& sources,
             const LowerOptions& options) {
  const bool startsAtSequence = mayStartAtSequence(unit);
  const bool returnsToSequence = mayReturnToSequence(unit);
  Module m;
  m.functions.resize(unit.programs.size());
  for (std::size_t i = 0; i < unit.programs.size(); ++i) {
    const Program& p = unit.programs[i];
    Function& fn = m.functions[i];
    fn.name = p.name;
    fn.number = p.number;
    fn.file = sources.name(p.file);
    FunctionLowering(p, m, fn, options, startsAtSequence, returnsToSequence)
        .run();
  }
  return m;
}

} // namespace mbc::ir
