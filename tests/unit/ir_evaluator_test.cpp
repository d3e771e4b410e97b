// The IR evaluator on hand-built modules: phis, alarms, NC blocks, G65 and
// M98 calls with their returns (M99, M99 P), computed GOTO and DPRNT.
#include "ir/evaluator.h"

#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace mbc::ir {
namespace {

using mbc::test::Machine;
using mbc::test::status;

struct W {
  char letter;
  WordKind kind;
  ValueId value;
};

/// Appends blocks and instructions to one function of a module.
class Builder {
public:
  Builder(Module& m, const std::string& name, int number) : m_(m) {
    index_ = m.functions.size();
    m.functions.emplace_back();
    fn().name = name;
    fn().number = number;
    fn().file = "test.nc";
    block();
  }

  Function& fn() { return m_.functions[index_]; }

  Inst& inst(ValueId id) { return fn().insts[id]; }

  BlockId block() {
    fn().blocks.emplace_back();
    return static_cast<BlockId>(fn().blocks.size() - 1);
  }

  void at(BlockId b) { cur_ = b; }

  ValueId emit(Op op, std::vector<ValueId> ops = {}) {
    Inst i;
    i.op = op;
    i.type = opInfo(op).result;
    i.block = cur_;
    i.ops = std::move(ops);
    i.data = payloadOf(op);
    auto id = static_cast<ValueId>(fn().insts.size());
    fn().insts.push_back(std::move(i));
    fn().blocks[cur_].insts.push_back(id);
    return id;
  }

  ValueId num(double v) {
    ValueId id = emit(Op::Const);
    inst(id).data = Number{v};
    return id;
  }

  void begin(int line) {
    inst(emit(Op::Begin)).data = SourceLine{static_cast<std::uint32_t>(line)};
  }

  ValueId ld(int var) {
    ValueId id = emit(Op::LdVar);
    inst(id).data = VarNumber{var};
    return id;
  }

  void st(int var, ValueId v) {
    inst(emit(Op::StVar, {v})).data = VarNumber{var};
  }

  void st(int var, double v) { st(var, num(v)); }

  ValueId nc(const std::vector<W>& words) { return wordOp(Op::Nc, {}, words); }

  ValueId callMacro(double p, double l, const std::vector<W>& args) {
    ValueId pv = num(p);
    ValueId lv = num(l);
    return wordOp(Op::CallMacro, {pv, lv}, args);
  }

  void term(Op op, std::vector<BlockId> targets = {},
            std::vector<ValueId> ops = {},
            std::vector<std::int64_t> cases = {}) {
    ValueId id = emit(op, std::move(ops));
    inst(id).targets = std::move(targets);
    if (op == Op::Switch || op == Op::Resume) {
      inst(id).data = SequenceCases{std::move(cases)};
    }
  }

  /// resume %f, next [cases[i]: targets[i]].
  void resume(ValueId f, BlockId next, std::vector<std::int64_t> cases = {},
              std::vector<BlockId> targets = {}) {
    targets.insert(targets.begin(), next);
    term(Op::Resume, std::move(targets), {f}, std::move(cases));
  }

private:
  ValueId wordOp(Op op, std::vector<ValueId> ops, const std::vector<W>& ws) {
    Words words;
    for (const W& w : ws) {
      ops.push_back(w.value);
      words.words.push_back({w.letter, w.kind});
    }
    ValueId id = emit(op, std::move(ops));
    inst(id).data = std::move(words);
    return id;
  }

  Module& m_;
  std::size_t index_ = 0;
  BlockId cur_ = 0;
};

mbrt_status run(const Module& m, Machine& machine, unsigned skipMask = 0) {
  mbrt_set_block_skip(machine.ctx(), skipMask);
  return evaluate(m, 0, machine.ctx());
}

mbrt_stats stats(const Machine& machine) {
  mbrt_stats s{};
  mbrt_get_stats(machine.ctx(), &s);
  return s;
}

TEST(IrEval, LoopWithPhisUsesParallelCopies) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId head = b.block(), body = b.block(), exit = b.block();
  b.begin(1);
  ValueId zero = b.num(0), one = b.num(1), limit = b.num(5);
  ValueId x0 = b.num(1), y0 = b.num(2);
  b.term(Op::Br, {head});
  b.at(head);
  ValueId i = b.emit(Op::Phi), sum = b.emit(Op::Phi);
  ValueId x = b.emit(Op::Phi), y = b.emit(Op::Phi);
  b.term(Op::CondBr, {body, exit}, {b.emit(Op::Lt, {i, limit})});
  b.at(body);
  b.begin(2);
  ValueId i2 = b.emit(Op::Add, {i, one});
  ValueId sum2 = b.emit(Op::Add, {sum, i});
  b.term(Op::Br, {head});
  // x, y = y, x on every iteration: a sequential copy would lose one.
  auto inputs = [&](ValueId phi, ValueId entry, ValueId back) {
    b.inst(phi).ops = {entry, back};
    b.inst(phi).targets = {0, body};
  };
  inputs(i, zero, i2);
  inputs(sum, zero, sum2);
  inputs(x, x0, y);
  inputs(y, y0, x);
  b.at(exit);
  b.st(100, sum);
  b.st(101, i);
  b.st(102, x);
  b.st(103, y);
  b.term(Op::Ret);

  Machine machine;
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  EXPECT_EQ(machine.read(100), 10.0);
  EXPECT_EQ(machine.read(101), 5.0);
  EXPECT_EQ(machine.read(102), 2.0);
  EXPECT_EQ(machine.read(103), 1.0);
  EXPECT_EQ(stats(machine).blocks, 6u);
  EXPECT_EQ(stats(machine).main_m99, 0);
}

TEST(IrEval, DivisionByZeroRaisesPS0112) {
  Module m;
  Builder b(m, "O1000", 1000);
  b.begin(7);
  ValueId q = b.emit(Op::Div, {b.num(1), b.num(0)});
  b.st(100, q);
  b.term(Op::Ret);

  Machine machine;
  EXPECT_EQ(run(m, machine), status(AlarmId::ZeroDivide));
  EXPECT_EQ(mbrt_alarm(machine.ctx()), status(AlarmId::ZeroDivide));
  EXPECT_EQ(machine.report(), "test.nc:7: alarm PS0112: ZERO DIVIDE\n");
  EXPECT_TRUE(isVacant(machine.read(100)));
}

// A module the evaluator cannot run is the compiler's fault: MBC0006
// INTERNAL COMPILER ERROR (mbc exits 4), never MBC0001 "not supported".
TEST(IrEval, AMalformedModuleIsAnInternalError) {
  Module m;
  Builder b(m, "O1000", 1000);
  b.begin(3);
  b.term(Op::Unreachable);

  Machine machine;
  EXPECT_EQ(run(m, machine), status(AlarmId::InternalError));
  EXPECT_NE(machine.report().find("MBC0006"), std::string::npos)
      << machine.report();
  Machine none;
  EXPECT_EQ(evaluate(Module{}, 0, none.ctx()), status(AlarmId::InternalError));
}

TEST(IrEval, NcBlocksMoveAndDropVacantWords) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId second = b.block(), third = b.block(), done = b.block();
  b.begin(3);
  b.resume(b.nc({{'G', WordKind::Int, b.num(1)},
                 {'Y', WordKind::Dec, b.num(7)},
                 {'F', WordKind::Val, b.num(200)}}),
           second);
  b.at(second);
  b.begin(4);
  b.resume(b.nc({{'X', WordKind::Dec, b.num(10)},
                 {'Y', WordKind::Var, b.ld(1)},
                 {'Z', WordKind::NegVar, b.ld(2)}}),
           third);
  b.at(third);
  b.begin(5);
  b.resume(b.nc({{'X', WordKind::Int, b.num(2000)}}), done);
  b.at(done);
  b.term(Op::Ret);

  Machine machine;
  ASSERT_EQ(machine.write(2, 5), 0);
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  const std::vector<mbrt_motion>& mv = machine.motions();
  ASSERT_EQ(mv.size(), 3u);
  EXPECT_EQ(mv[0].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(mv[0].feed, 200.0);
  EXPECT_EQ(mv[1].end[0], 10.0);
  EXPECT_EQ(mv[1].end[1], 7.0); // Y#1 with #1 vacant: no Y word
  EXPECT_EQ(mv[1].end[2], -5.0);
  EXPECT_EQ(mv[1].line, 4);
  EXPECT_STREQ(mv[1].file, "test.nc");
  EXPECT_EQ(mv[2].end[0], 2.0); // X2000 without decimal point
}

// O9001 adds its argument A (#1) to #100.
void addArgumentMacro(Module& m) {
  Builder c(m, "O9001", 9001);
  c.begin(10);
  c.st(100, c.emit(Op::Add, {c.ld(100), c.ld(1)}));
  c.term(Op::Ret);
}

TEST(IrEval, MacroCallPassesArgumentsAndRepeats) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId after = b.block();
  b.begin(1);
  b.resume(b.callMacro(9001, 2, {{'A', WordKind::Dec, b.num(3)}}), after);
  b.at(after);
  b.begin(2);
  b.st(101, b.ld(1));
  b.resume(b.callMacro(9001, 0, {{'A', WordKind::Dec, b.num(50)}}), b.block());
  b.at(2);
  b.term(Op::Ret);
  addArgumentMacro(m);

  Machine machine;
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  EXPECT_EQ(machine.read(100), 6.0);        // two runs of A3.
  EXPECT_TRUE(isVacant(machine.read(101))); // the caller's #1
  EXPECT_EQ(mbrt_call_depth(machine.ctx()), 0);
  EXPECT_EQ(stats(machine).blocks, 4u);
}

TEST(IrEval, MacroCallOfAMissingProgram) {
  Module m;
  Builder b(m, "O1000", 1000);
  b.begin(4);
  b.resume(b.callMacro(9002, 1, {}), b.block());
  b.at(1);
  b.term(Op::Ret);
  addArgumentMacro(m);

  Machine machine;
  EXPECT_EQ(run(m, machine), status(AlarmId::ProgramNotFound));
  EXPECT_EQ(machine.report(),
            "test.nc:4: alarm PS0076: PROGRAM NOT FOUND: O9002\n");
}

TEST(IrEval, RunawayRecursionStopsAtTheNestingLimit) {
  Module m;
  Builder b(m, "O9001", 9001);
  b.begin(1);
  b.resume(b.callMacro(9001, 1, {}), b.block());
  b.at(1);
  b.term(Op::Ret);

  Machine machine;
  EXPECT_EQ(run(m, machine), status(AlarmId::TooManyMacroNesting));
}

// O2000: #100 = #100 + 1, #1 = 7, then M99 [P seq].
void countingSubprogram(Module& m, int seq) {
  Builder c(m, "O2000", 2000);
  BlockId after = c.block();
  c.begin(10);
  c.st(100, c.emit(Op::Add, {c.ld(100), c.num(1)}));
  c.st(1, 7.0);
  std::vector<W> words{{'M', WordKind::Int, c.num(99)}};
  if (seq) {
    words.push_back({'P', WordKind::Int, c.num(seq)});
  }
  c.resume(c.nc(words), after);
  c.at(after);
  c.st(102, 1.0); // not reached: M99 leaves
  c.term(Op::Ret);
}

TEST(IrEval, M98RunsTheSubprogramLTimesOnTheSameLocals) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId after = b.block();
  b.begin(1);
  b.resume(b.nc({{'M', WordKind::Int, b.num(98)},
                 {'P', WordKind::Int, b.num(2000)},
                 {'L', WordKind::Int, b.num(3)}}),
           after);
  b.at(after);
  b.begin(2);
  b.st(101, b.ld(1));
  b.term(Op::Ret);
  countingSubprogram(m, 0);

  Machine machine;
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  EXPECT_EQ(machine.read(100), 3.0);
  EXPECT_EQ(machine.read(101), 7.0);
  EXPECT_TRUE(isVacant(machine.read(102)));
}

// O1000: M98 P2000 (or G65 P2000), then N20 sets #101; the next block #103.
Module returnToSequence(int seq, bool macro) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId next = b.block(), n20 = b.block();
  b.begin(1);
  ValueId f = macro ? b.callMacro(2000, 1, {})
                    : b.nc({{'M', WordKind::Int, b.num(98)},
                            {'P', WordKind::Int, b.num(2000)}});
  b.resume(f, next, {20}, {n20});
  b.at(next);
  b.begin(2);
  b.st(103, 1.0);
  b.term(Op::Ret);
  b.at(n20);
  b.begin(3);
  b.st(101, 2.0);
  b.term(Op::Ret);
  countingSubprogram(m, seq);
  return m;
}

TEST(IrEval, M99PResumesAtTheCaseOfTheCaller) {
  for (bool macro : {false, true}) {
    Module m = returnToSequence(20, macro);
    Machine machine;
    ASSERT_EQ(run(m, machine), 0) << machine.report();
    EXPECT_EQ(machine.read(100), 1.0) << macro;
    EXPECT_EQ(machine.read(101), 2.0) << macro;
    EXPECT_TRUE(isVacant(machine.read(103))) << macro;
    EXPECT_TRUE(isVacant(machine.read(102))) << macro;
    EXPECT_EQ(stats(machine).blocks, 3u) << macro;
  }
}

TEST(IrEval, M99PToAMissingSequenceNumber) {
  Module m = returnToSequence(30, false);
  Machine machine;
  EXPECT_EQ(run(m, machine), status(AlarmId::IllegalMacroSequenceNumber));
  EXPECT_EQ(machine.report(), "test.nc:10: alarm PS0128: ILLEGAL MACRO "
                              "SEQUENCE NUMBER: N30 not found in O1000\n");
}

Module computedGoto(double target) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId n10 = b.block();
  b.begin(5);
  b.term(Op::Switch, {n10}, {b.num(target)}, {10});
  b.at(n10);
  b.begin(6);
  b.st(100, 1.0);
  b.term(Op::Ret);
  return m;
}

TEST(IrEval, SwitchRoundsAndFindsTheCase) {
  Module m = computedGoto(9.6);
  Machine machine;
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  EXPECT_EQ(machine.read(100), 1.0);
}

TEST(IrEval, SwitchWithoutTheCaseRaisesPS0128) {
  Module m = computedGoto(25);
  Machine machine;
  EXPECT_EQ(run(m, machine), status(AlarmId::IllegalMacroSequenceNumber));
  EXPECT_EQ(machine.report(), "test.nc:5: alarm PS0128: ILLEGAL MACRO "
                              "SEQUENCE NUMBER: N25 not found in O1000\n");
  Module zero = computedGoto(0);
  Machine other;
  EXPECT_EQ(run(zero, other), status(AlarmId::IllegalMacroSequenceNumber));
  EXPECT_NE(other.report().find("GOTO 0"), std::string::npos) << other.report();
}

TEST(IrEval, DprntPrintsTextAndValues) {
  Module m;
  m.strings = {"X", "*Y"};
  Builder b(m, "O1000", 1000);
  b.begin(1);
  ValueId v = b.num(1.5);
  ValueId w = b.ld(1);
  ValueId p = b.emit(Op::Dprnt, {v, w});
  b.inst(p).data = PrintItems{{{1}, {0, 5, 3}, {2}, {0, 2, 1}}};
  b.term(Op::Ret);

  Machine machine;
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  EXPECT_EQ(machine.printed(), "X     1.500 Y  0.0\n");
}

TEST(IrEval, M99InMainAndM30InACalleeEndTheRun) {
  Module m;
  Builder b(m, "O1000", 1000);
  BlockId after = b.block();
  b.begin(1);
  b.resume(b.nc({{'M', WordKind::Int, b.num(99)}}), after);
  b.at(after);
  b.st(100, 1.0);
  b.term(Op::Ret);
  Machine machine;
  ASSERT_EQ(run(m, machine), 0) << machine.report();
  EXPECT_EQ(stats(machine).main_m99, 1);
  EXPECT_TRUE(isVacant(machine.read(100)));

  Module n;
  Builder main(n, "O1000", 1000);
  BlockId next = main.block();
  main.resume(main.callMacro(9001, 3, {}), next);
  main.at(next);
  main.st(100, 1.0);
  main.term(Op::Ret);
  Builder callee(n, "O9001", 9001);
  callee.st(101, callee.emit(Op::Add, {callee.ld(101), callee.num(1)}));
  callee.resume(callee.nc({{'M', WordKind::Int, callee.num(30)}}), 1);
  callee.block();
  callee.at(1);
  callee.term(Op::Ret);
  Machine other;
  ASSERT_EQ(run(n, other), 0) << other.report();
  EXPECT_EQ(other.read(101), 1.0); // no second repetition
  EXPECT_TRUE(isVacant(other.read(100)));
  EXPECT_EQ(stats(other).main_m99, 0);
}

TEST(IrEval, BlockSkipFollowsTheMask) {
  for (unsigned mask : {0U, 1U << 2}) {
    Module m;
    Builder b(m, "O1000", 1000);
    BlockId body = b.block(), done = b.block();
    ValueId skip = b.emit(Op::BlockSkip);
    b.inst(skip).data = SkipSwitch{2};
    b.term(Op::CondBr, {done, body}, {skip});
    b.at(body);
    b.st(100, 1.0);
    b.term(Op::Br, {done});
    b.at(done);
    b.term(Op::Ret);
    Machine machine;
    ASSERT_EQ(run(m, machine, mask), 0) << machine.report();
    EXPECT_EQ(isVacant(machine.read(100)), mask != 0) << mask;
  }
}

} // namespace
} // namespace mbc::ir
