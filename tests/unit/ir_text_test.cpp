// The IR text form (docs/ir.md, "Text form"): print(parse(text)) == text for
// functions that use every operation and every syntax form, the fields the
// parser fills in, and parse errors with their line:col.
#include "ir/ir_parser.h"
#include "ir/printer.h"
#include "ir/verifier.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "ir_test_support.h"

namespace mbc::ir {
namespace {

// A counting loop with a phi, DPRNT/BPRNT, a G65 call, and a named program.
constexpr std::string_view kLoopAndCall = R"mbir(func @MAIN "main.nc" {
b0:
  begin 1
  popen
  %1 = const 0
  stvar #1, %1
  br b1
b1:
  %3 = phi num [%1, b0], [%9, b2]
  begin 2
  %4 = const 3
  %5 = lt %3, %4
  trace "WHILE [{?}] DO1", %5
  condbr %5, b2, b3
b2:
  begin 3
  %7 = const 1
  %9 = add %3, %7
  stvar #1, %9
  br b1
b3:
  begin 5
  %11 = ldvar #1
  dprnt "X", %11[53], "*Y\"Q\"", %3[33]
  bprnt "C", %11[3]
  pclos
  %14 = const 1000
  %15 = const 1
  %16 = vacant
  %17 = call.macro %14, %15, A:dec %16, B:val %11
  resume %17, b4 [10: b5]
b4:
  begin 6
  ret
b5:
  begin 7 !8
  %20 = ldvar #3
  %23 = tonum %20
  %21 = ldind %23 !9
  %22 = adp %23
  stind %23, %22, "MSG \\ DONE"
  unreachable
}

func @<DRILL_CYCLE> #100000000 "lib.nc" {
b0:
  %5 = startseq
  %6 = const 0
  %7 = eq %5, %6
  condbr %7, b1, b4
b1:
  begin 2
  %0 = ldvar #26
  %1 = const 0.25
  %2 = const 2
  %3 = call.macro %1, %2
  resume %3, b2, b3
b2:
  begin 3
  ret
b3:
  %4 = retseq
  switch %4 [3: b2]
b4:
  switch %5 [3: b2]
b5:
  begin 4
  raise PS0114, "expected ']' to close '['"
}
)mbir";

// Arithmetic, builtins, an NC block with every word kind, a block skip, a
// computed GOTO and an alarm message.
constexpr std::string_view kArithmetic = R"mbir(func @O1000 #1000 "prog.nc" {
b0:
  %0 = blockskip 1 !3
  condbr %0, b2, b1
b1:
  begin 3
  %2 = ldvar #24
  %3 = ldvar #26
  %4 = const 10.5
  %5 = const 0.1
  %44 = tonum %2
  %6 = sub %44, %5
  %7 = mul %6, %4
  %8 = div %7, %5
  %9 = mod %8, %4
  %45 = tonum %2
  %46 = tonum %3
  %10 = and %45, %46
  %47 = tonum %3
  %11 = or %10, %47
  %12 = xor %11, %9
  %13 = neg %12
  %14 = tonum %13
  %15 = fn SIN, %14
  %16 = fn ATAN2, %15, %5
  %17 = fn POW, %16, %4
  %18 = round.addr X, %17
  %60 = prm 3, %4, %5, %5
  %19 = const 1
  %20 = const -2.5
  %21 = nc G:int %19, X:dec %20, Y:var %2, Z:nvar %3, F:val %18, r:dec %20
  resume %21, b2 [10: b2, 20: b3]
b2:
  begin 4
  %23 = ldvar #1
  %24 = const 1e+20
  %25 = eq %23, %24
  %26 = ne %23, %24
  %48 = tonum %23
  %27 = gt %48, %24 !5
  %49 = tonum %23
  %28 = ge %49, %24
  %50 = tonum %23
  %29 = le %50, %24
  %30 = land %25, %26
  %31 = lor %30, %27
  %32 = lxor %31, %28
  %33 = land %32, %29
  condbr %33, b3, b4
b3:
  begin 8
  %35 = ldvar #100
  switch %35 [10: b2, 20: b3, 99999: b4]
b4:
  begin 9
  %37 = const 3001
  stvar #3000, %37, "TOOL \"T1\" BROKEN"
  %39 = nc
  resume %39, b5 [10: b2, 20: b3]
b5:
  begin 10
  %41 = const -0
  %42 = const 1e-07
  %43 = fn ROUND, %41
  stvar #500, %43
  ret
}
)mbir";

std::string parseError(std::string_view text) {
  Module m;
  std::string error;
  EXPECT_FALSE(parseModule(text, m, error));
  return error;
}

TEST(IrText, RoundTripsLoopAndCall) {
  Module m = parseText(kLoopAndCall);
  EXPECT_EQ(print(m), kLoopAndCall);
  EXPECT_EQ(verify(m), std::vector<std::string>{});
}

TEST(IrText, RoundTripsArithmeticAndNc) {
  Module m = parseText(kArithmetic);
  EXPECT_EQ(print(m), kArithmetic);
  EXPECT_EQ(verify(m), std::vector<std::string>{});
}

TEST(IrText, TestsUseEveryOperation) {
  std::set<Op> used;
  for (std::string_view text : {kLoopAndCall, kArithmetic}) {
    Module m = parseText(text);
    for (const Function& f : m.functions) {
      for (const Block& b : f.blocks) {
        for (ValueId id : b.insts) {
          used.insert(f.insts[id].op);
        }
      }
    }
  }
#define OP(Name, Mnemonic, Result, Operands, Takes, Flags, Math, Format)       \
  EXPECT_TRUE(used.count(Op::Name)) << Mnemonic;
#include "ir/opcodes.def"
}

TEST(IrText, PrintsOneFunctionAlone) {
  Module m = parseText(kLoopAndCall);
  std::string second = print(m, m.functions[1]);
  EXPECT_EQ(second, kLoopAndCall.substr(kLoopAndCall.find("func @<")));
}

TEST(IrText, KeepsIdsAndPutsOthersAfterTheLargest) {
  Module m = parseText(R"mbir(func @O1 "a.nc" {
b0:
  %7 = const 2
  stvar #1, %7
  ret
}
)mbir");
  const Function& f = m.functions[0];
  ASSERT_EQ(f.insts.size(), 10U); // %0..%7, then stvar and ret
  EXPECT_EQ(f.blocks[0].insts, (std::vector<ValueId>{7, 8, 9}));
  EXPECT_EQ(f.insts[0].op, Op::Unreachable);
  EXPECT_EQ(f.insts[0].type, Type::None);
  EXPECT_EQ(f.insts[7].type, Type::Num);
  EXPECT_EQ(f.insts[8].op, Op::StVar);
  EXPECT_EQ(f.insts[8].get<VarNumber>().number, 1);
}

TEST(IrText, FillsFieldsAsIrHDescribes) {
  Module m = parseText(kLoopAndCall);
  const Function& f = m.functions[0];
  EXPECT_EQ(f.number, -1);
  EXPECT_EQ(f.name, "MAIN");
  EXPECT_EQ(m.functions[1].name, "<DRILL_CYCLE>");
  const Inst& call = f.insts[17];
  EXPECT_EQ(call.ops, (std::vector<ValueId>{14, 15, 16, 11}));
  EXPECT_EQ(
      call.get<Words>().words,
      (std::vector<AddressWord>{{'A', WordKind::Dec}, {'B', WordKind::Val}}));
  const Inst& resume = f.insts[f.blocks[3].insts.back()];
  EXPECT_EQ(resume.targets, (std::vector<BlockId>{4, 5}));
  EXPECT_EQ(resume.get<SequenceCases>().numbers,
            (std::vector<std::int64_t>{10}));
  EXPECT_FALSE(resume.get<SequenceCases>().landing);
  const std::vector<PrintItem>& items =
      f.insts[f.blocks[3].insts[2]].get<PrintItems>().items;
  ASSERT_EQ(items.size(), 4U);
  EXPECT_EQ(m.strings[items[0].text - 1], "X");
  EXPECT_EQ(items[1], (PrintItem{0, 5, 3}));
  EXPECT_EQ(m.strings[items[2].text - 1], "*Y\"Q\"");
  const StringRef message = f.insts[f.blocks[5].insts[5]].get<Message>().text;
  ASSERT_NE(message, 0U);
  EXPECT_EQ(m.strings[message - 1], "MSG \\ DONE");
}

TEST(IrText, LinesFollowTheLastBegin) {
  Module m = parseText(kLoopAndCall);
  const Function& f = m.functions[0];
  EXPECT_EQ(f.insts[3].line, 0U); // phi before any begin of b1
  EXPECT_EQ(f.insts[4].line, 2U);
  const std::vector<ValueId>& b5 = f.blocks[5].insts;
  EXPECT_EQ(f.insts[b5[0]].line, 8U); // begin 7 !8
  EXPECT_EQ(f.insts[20].line, 7U);    // the begin's number, not its line
  EXPECT_EQ(f.insts[21].line, 9U);
  EXPECT_EQ(f.insts[22].line, 7U);
}

TEST(IrText, EmptyBlockPrintsItsLabel) {
  constexpr std::string_view text = R"mbir(func @O2 #2 "" {
b0:
b1:
  unreachable
}
)mbir";
  EXPECT_EQ(print(parseText(text)), text);
}

TEST(IrText, AcceptsCommentsAndBlankLines) {
  Module m = parseText(R"mbir(; a test
func @O3 "c.nc" {   ; header

b0:
  %1 = const 1   ; one
  stvar #1, %1 !4
  ret
}
)mbir");
  EXPECT_EQ(print(m), R"mbir(func @O3 "c.nc" {
b0:
  %1 = const 1
  stvar #1, %1 !4
  ret
}
)mbir");
}

TEST(IrText, EmptyModule) {
  Module m = parseText("  ; nothing\n\n");
  EXPECT_TRUE(m.functions.empty());
  EXPECT_EQ(print(m), "");
}

TEST(IrText, ErrorsGiveLineAndColumn) {
  EXPECT_EQ(parseError("fun @O1 \"\" {\n}\n"), "1:1: expected 'func'");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %1 = frob %2\n}\n"),
            "3:8: unknown operation 'frob'");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %1 = fn SINE, %2\n}\n"),
            "3:11: unknown builtin 'SINE'");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %1 = vacant\n  %1 = vacant\n"
                       "}\n"),
            "4:3: value %1 is defined twice");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb1:\n}\n"),
            "2:1: expected label b0: blocks are numbered in order from b0");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %3 = stvar #1, %1\n}\n"),
            "3:3: 'stvar' defines no value");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  const 1\n}\n"),
            "3:3: 'const' defines a value: write '%N = const'");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  br b1 b2\n}\n"),
            "3:9: unexpected 'b' at the end of the line");
  EXPECT_EQ(parseError("func @O1 \"\" {\n  ret\n}\n"),
            "2:3: instruction outside a block (expected label b0:)");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  ret\n"),
            "4:1: missing '}' at the end of @O1");
  EXPECT_EQ(parseError("func @O1 \"a\\n\" {\n}\n"),
            "1:13: unknown escape in string (only \\\" and \\\\)");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %1 = const x1\n}\n"),
            "3:14: expected a number");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %1 = nc X:flt %2\n}\n"),
            "3:13: unknown word kind 'flt'");
  // ,C ,R ,A are the lower-case c, r, a; no other lower-case letter is.
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  %1 = nc b:dec %2\n}\n"),
            "3:11: 'b' is not an address letter");
  EXPECT_EQ(parseError("func @O1 \"\" {\nb0:\n  switch %1 [10 b2]\n}\n"),
            "3:17: expected ':'");
}

TEST(IrText, ErrorLeavesTheModuleAlone) {
  Module m = parseText(kArithmetic);
  std::string error;
  EXPECT_FALSE(parseModule("func", m, error));
  EXPECT_EQ(print(m), kArithmetic);
}

} // namespace
} // namespace mbc::ir
