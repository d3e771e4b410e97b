// The IR verifier (docs/ir.md, "Invariants"): valid functions pass and each
// invariant has a negative test with its message. Also the CFG it builds on:
// successors, predecessors, RPO and dominators, unreachable blocks included.
#include "ir/cfg.h"
#include "ir/ir_parser.h"
#include "ir/verifier.h"
#include <mbc/alarm.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ir_test_support.h"

namespace mbc::ir {
namespace {

using Messages = std::vector<std::string>;

Messages verifyText(std::string_view text) {
  return verify(parseText(text));
}

// b0 -> b1 (loop header) <-> b2 (body); b1 -> b3 (exit); b4 unreachable.
constexpr std::string_view kLoop = R"mbir(func @O1000 #1000 "loop.nc" {
b0:
  begin 1
  %1 = const 0
  br b1
b1:
  %3 = phi num [%1, b0], [%6, b2]
  %4 = const 10
  %5 = lt %3, %4
  condbr %5, b2, b3
b2:
  %6 = add %3, %4
  br b1
b3:
  stvar #1, %3
  ret
b4:
  %9 = add %6, %12
  %12 = const 1
  br b4
}
)mbir";

TEST(IrVerifier, AcceptsLoopWithPhiAndUnreachableBlock) {
  EXPECT_EQ(verifyText(kLoop), Messages{});
}

// raise ends a block the control cannot read: it names an alarm that has a
// code (a #3000 macro alarm has none of its own).
TEST(IrVerifier, RaiseNamesAnAlarmWithACode) {
  Module m = parseText(R"mbir(func @O1 #1 "" {
b0:
  begin 1
  raise PS0114, "expected an expression"
}
)mbir");
  EXPECT_EQ(verify(m), Messages{});
  for (Inst& inst : m.functions[0].insts) {
    if (inst.op == Op::Raise) {
      inst.get<AlarmRaise>().alarm = mbc::AlarmId::MacroAlarm;
    }
  }
  const Messages messages = verify(m);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("which has no code"), std::string::npos)
      << messages[0];
}

// retseq reads the N of the M99 P that entered its block: only landing
// edges (maybe through a pad that branches on) may enter it.
TEST(IrVerifier, RetseqOnlyBehindLandingEdges) {
  EXPECT_EQ(verifyText(R"mbir(func @O1 #1 "" {
b0:
  %0 = const 2
  %1 = call.macro %0, %0
  resume %1, b1, b3
b1:
  %2 = nc
  resume %2, b2, b4
b2:
  ret
b3:
  br b4
b4:
  %3 = retseq
  switch %3 [5: b2]
}
)mbir"),
            Messages{});
  Messages m = verifyText(R"mbir(func @O1 #1 "" {
b0:
  %0 = const 2
  %1 = call.macro %0, %0
  resume %1, b2, b2
b1:
  ret
b2:
  %3 = retseq
  switch %3 [5: b1]
}
)mbir");
  ASSERT_EQ(m.size(), 1U);
  EXPECT_NE(m[0].find("b0 enters b2 other than by an M99 P landing edge"),
            std::string::npos)
      << m[0];
}

TEST(IrVerifier, AcceptsSwitchCasesSharingABlock) {
  EXPECT_EQ(verifyText(R"mbir(func @O1 "" {
b0:
  %0 = ldvar #1
  switch %0 [1: b1, 2: b1, 3: b2]
b1:
  %2 = phi vnum [%0, b0]
  ret
b2:
  ret
}
)mbir"),
            Messages{});
}

TEST(IrVerifier, MissingTerminator) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  stvar #1, %1\n}\n"),
            Messages{"@O1 b0: block does not end with a terminator"});
}

TEST(IrVerifier, EmptyBlock) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  br b1\nb1:\n}\n"),
            Messages{"@O1 b1: block is empty: it needs a terminator"});
}

TEST(IrVerifier, TerminatorInTheMiddle) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  br b1\n  ret\nb1:\n  ret\n}\n"),
            Messages{"@O1 b0: br b1: terminator in the middle of the block"});
}

TEST(IrVerifier, WrongOperandCount) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  %2 = add %1\n  ret\n}\n"),
            Messages{"@O1 b0: %2 = add %1: expected 2 operand(s), got 1"});
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  %2 = fn ATAN2, %1\n  ret\n}\n"),
            Messages{"@O1 b0: %2 = fn ATAN2, %1: expected 2 operand(s) for "
                     "ATAN2, got 1"});
}

TEST(IrVerifier, WordDescriptorsMatchOperands) {
  Module m = parseText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  %2 = nc X:int %1, Y:dec %1\n  resume %2, b0 []\n}\n");
  m.functions[0].insts[2].get<Words>().words.pop_back();
  EXPECT_EQ(verify(m), Messages{"@O1 b0: %2 = nc X:int %1, ?:int %1: expected "
                                "1 operand(s) for the words, got 2"});
}

// Each op has the payload opcodes.def names: a ldvar holding a builtin is
// caught before anything reads it.
TEST(IrVerifier, PayloadIsTheOneTheOpHas) {
  Module m = parseText("func @O1 \"\" {\nb0:\n  %1 = ldvar #1\n  ret\n}\n");
  EXPECT_EQ(verify(m), Messages{});
  m.functions[0].insts[1].data = BuiltinFn{Builtin::Sqrt};
  EXPECT_EQ(verify(m),
            Messages{"@O1 b0: %1 = ldvar <payload?>: the payload is not the "
                     "one ldvar has (opcodes.def)"});
}

TEST(IrVerifier, PrintItemsMatchOperands) {
  Module m = parseText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  dprnt \"X\", %1[53]\n  ret\n}\n");
  m.functions[0].insts[2].ops.push_back(1);
  EXPECT_EQ(verify(m), Messages{"@O1 b0: dprnt \"X\", %1[53]: expected 1 "
                                "operand(s) for the value items, got 2"});
}

TEST(IrVerifier, BoolWhereNumExpected) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  %2 = eq %1, %1\n  %3 = add %1, %2\n  ret\n}\n"),
            Messages{"@O1 b0: %3 = add %1, %2: operand %2 is bool, expected "
                     "num"});
}

TEST(IrVerifier, ConditionAndFlowTypes) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %1 = const 1\n"
                       "  condbr %1, b1, b1\nb1:\n  resume %1, b1 []\n}\n"),
            (Messages{"@O1 b0: condbr %1, b1, b1: operand %1 is num, "
                      "expected bool",
                      "@O1 b1: resume %1, b1 []: operand %1 is num, "
                      "expected flow"}));
}

TEST(IrVerifier, UndefinedOperand) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %1 = neg %42\n  ret\n}\n"),
            Messages{"@O1 b0: %1 = neg %42: operand %42 is not defined"});
}

TEST(IrVerifier, UseNotDominated) {
  EXPECT_EQ(verifyText(R"mbir(func @O1000 "" {
b0:
  %5 = const 1
  %1 = ldvar #1
  %2 = eq %1, %5
  condbr %2, b1, b2
b1:
  %9 = const 2
  br b2
b2:
  %7 = add %5, %9
  ret
}
)mbir"),
            Messages{"@O1000 b2: %7 = add %5, %9: operand %9 does not "
                     "dominate its use"});
}

TEST(IrVerifier, UseBeforeDefinitionInABlock) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %2 = neg %1\n"
                       "  %1 = const 1\n  ret\n}\n"),
            Messages{"@O1 b0: %2 = neg %1: operand %1 does not dominate its "
                     "use"});
}

TEST(IrVerifier, PhiInputMustDominateItsIncomingBlock) {
  EXPECT_EQ(verifyText(R"mbir(func @O1 "" {
b0:
  %1 = const 1
  br b1
b1:
  %3 = phi num [%4, b0]
  %4 = const 2
  ret
}
)mbir"),
            Messages{"@O1 b1: %3 = phi num [%4, b0]: operand %4 does not "
                     "dominate the end of b0"});
}

TEST(IrVerifier, PhiArityMismatch) {
  std::string text(kLoop);
  text.replace(text.find("[%1, b0], [%6, b2]"), 18, "[%1, b0]");
  EXPECT_EQ(
      verify(parseText(text)),
      Messages{"@O1000 b1: %3 = phi num [%1, b0]: phi has 1 input(s) for 2 "
               "predecessor(s)"});
}

TEST(IrVerifier, PhiInputFromANonPredecessor) {
  std::string text(kLoop);
  text.replace(text.find("[%6, b2]"), 8, "[%1, b3]");
  EXPECT_EQ(verify(parseText(text)),
            Messages{"@O1000 b1: %3 = phi num [%1, b0], [%1, b3]: b3 is not a "
                     "predecessor"});
}

TEST(IrVerifier, PhiAfterOtherInstructions) {
  std::string text(kLoop);
  text.replace(text.find("  %3 = phi"), 0, "  %2 = const 5\n");
  EXPECT_EQ(verify(parseText(text)),
            Messages{"@O1000 b1: %3 = phi num [%1, b0], [%6, b2]: phi after a "
                     "non-phi instruction"});
}

// Arithmetic reads numbers: a value that may be vacant goes through tonum
// first, and a num phi takes no vnum input.
TEST(IrVerifier, VacantValuesNeedTonum) {
  EXPECT_EQ(verifyText(R"mbir(func @O1 "" {
b0:
  %0 = ldvar #1
  %1 = const 2
  %2 = mul %0, %1
  %3 = tonum %0
  %4 = mul %3, %1
  %5 = eq %0, %1
  stvar #2, %0
  br b1
b1:
  %6 = phi num [%0, b0]
  %7 = phi vnum [%4, b0]
  ret
}
)mbir"),
            (Messages{"@O1 b0: %2 = mul %0, %1: operand %0 is vnum, expected "
                      "num",
                      "@O1 b1: %6 = phi num [%0, b0]: operand %0 is vnum, "
                      "expected num"}));
}

// A trace takes one value per hole of its template, and no flow.
TEST(IrVerifier, TraceHolesAndTypes) {
  EXPECT_EQ(verifyText(R"mbir(func @O1 "" {
b0:
  %0 = const 1
  %1 = lt %0, %0
  trace "#{#} = {}", %0, %0
  trace "WHILE [{?}] DO1", %1
  trace "#5 = {}"
  %2 = nc
  trace "IF [{?}] GOTO", %2
  resume %2, b1 []
b1:
  ret
}
)mbir"),
            (Messages{"@O1 b0: trace \"#5 = {}\": expected 1 operand(s) for "
                      "the template's holes, got 0",
                      "@O1 b0: trace \"IF [{?}] GOTO\", %2: operand %2 is "
                      "flow, expected a value other than a flow"}));
}

TEST(IrVerifier, BadTarget) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  br b7\n}\n"),
            Messages{"@O1 b0: br b7: target b7 does not exist"});
}

TEST(IrVerifier, SwitchCases) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %0 = ldvar #1\n"
                       "  switch %0 [10: b0, 10: b0, 0: b0, 100000: b0]\n}\n"),
            (Messages{"@O1 b0: switch %0 [10: b0, 10: b0, 0: b0, 100000: b0]: "
                      "case 10 appears twice",
                      "@O1 b0: switch %0 [10: b0, 10: b0, 0: b0, 100000: b0]: "
                      "case 0 is not a sequence number (1..99999)",
                      "@O1 b0: switch %0 [10: b0, 10: b0, 0: b0, 100000: b0]: "
                      "case 100000 is not a sequence number (1..99999)"}));
}

TEST(IrVerifier, Attributes) {
  EXPECT_EQ(verifyText("func @O1 \"\" {\nb0:\n  %0 = ldvar #-1\n"
                       "  %1 = blockskip 0\n  %3 = tonum %0\n"
                       "  %2 = fn ADP, %3\n  ret\n}\n"),
            (Messages{"@O1 b0: %0 = ldvar #-1: variable number is negative",
                      "@O1 b0: %1 = blockskip 0: block skip switch outside "
                      "1..9",
                      "@O1 b0: %2 = fn ADP, %3: ADP is the adp operation, "
                      "never fn"}));
}

TEST(IrVerifier, StructureOfHandBuiltFunctions) {
  Module m = parseText("func @O1 \"\" {\nb0:\n  %0 = const 1\n  br b1\n"
                       "b1:\n  ret\n}\n");
  Function& f = m.functions[0];
  f.insts[0].type = Type::Bool;
  f.blocks[1].insts.insert(f.blocks[1].insts.begin(), 0);
  f.blocks[0].insts.insert(f.blocks[0].insts.begin(), 99);
  EXPECT_EQ(verify(m),
            (Messages{"@O1 b0: lists %99, which is not an instruction of the "
                      "function",
                      "@O1 b1: %0 = const 1: the instruction is also in b0",
                      "@O1 b0: %0 = const 1: type is bool, but const defines "
                      "num"}));
  m.functions.push_back(Function{});
  m.functions.back().name = "MAIN";
  EXPECT_EQ(verify(m).back(), "@MAIN: function has no blocks");
}

TEST(IrCfg, SuccessorsPredecessorsAndDominators) {
  Module m = parseText(kLoop);
  Cfg cfg = buildCfg(m.functions[0]);
  EXPECT_EQ(cfg.succs[1], (std::vector<BlockId>{2, 3}));
  EXPECT_EQ(cfg.succs[4], (std::vector<BlockId>{4}));
  EXPECT_EQ(cfg.preds[1], (std::vector<BlockId>{0, 2}));
  EXPECT_EQ(cfg.preds[4], (std::vector<BlockId>{4}));
  EXPECT_EQ(cfg.rpo, (std::vector<BlockId>{0, 1, 3, 2}));
  EXPECT_EQ(cfg.idom, (std::vector<BlockId>{0, 0, 1, 1, kNoBlock}));
  EXPECT_TRUE(cfg.dominates(1, 2));
  EXPECT_TRUE(cfg.dominates(0, 3));
  EXPECT_TRUE(cfg.dominates(2, 2));
  EXPECT_FALSE(cfg.dominates(2, 3));
  EXPECT_FALSE(cfg.dominates(2, 1));
  EXPECT_FALSE(cfg.reachable(4));
  EXPECT_FALSE(cfg.dominates(0, 4));
  EXPECT_FALSE(cfg.dominates(4, 0));
  EXPECT_TRUE(cfg.dominates(4, 4));
}

TEST(IrCfg, DiamondJoinsAtItsHead) {
  Module m = parseText(R"mbir(func @O1 "" {
b0:
  %0 = blockskip 1
  condbr %0, b1, b2
b1:
  br b3
b2:
  br b3
b3:
  ret
}
)mbir");
  Cfg cfg = buildCfg(m.functions[0]);
  EXPECT_EQ(cfg.idom, (std::vector<BlockId>{0, 0, 0, 0}));
  EXPECT_EQ(cfg.preds[3], (std::vector<BlockId>{1, 2}));
  EXPECT_FALSE(cfg.dominates(1, 3));
}

TEST(IrCfg, MalformedFunctionsDoNotCrash) {
  Function f;
  EXPECT_TRUE(buildCfg(f).rpo.empty());
  f.blocks.resize(2); // no instructions, so no edges
  Cfg cfg = buildCfg(f);
  EXPECT_EQ(cfg.rpo, (std::vector<BlockId>{0}));
  EXPECT_FALSE(cfg.reachable(1));
}

} // namespace
} // namespace mbc::ir
