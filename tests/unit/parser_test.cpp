// Parser and semantic checks: structure of the AST, FANUC precedence, and
// the diagnostics of classic mistakes.
#include "frontend/parser.h"
#include "frontend/sema.h"
#include <mbc/addresses.h>

#include <gtest/gtest.h>

namespace mbc {
namespace {

struct Parsed {
  SourceManager sources;
  DiagnosticEngine diags{sources};
  Unit unit;
  std::string text;
};

std::unique_ptr<Parsed> parse(const std::string& src, bool check = false) {
  auto p = std::make_unique<Parsed>();
  std::uint32_t id = p->sources.add("t.nc", src);
  ParseOptions o;
  o.checkWarnings = check;
  parseFile(p->sources, id, p->diags, o, p->unit);
  checkUnit(p->unit, p->diags);
  p->text = renderDiagnostics(p->diags);
  return p;
}

const Stmt& firstStmt(const Parsed& p) {
  return p.unit.programs.at(0).blocks.at(0).stmt;
}

TEST(Parser, ProgramsAndBlocks) {
  auto p = parse("%\nO1000 (MAIN)\nN10 G00 X1.\n#1=2\nM30\nO2000\nM99\n%\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  ASSERT_EQ(p->unit.programs.size(), 2u);
  EXPECT_EQ(p->unit.programs[0].name, "O1000");
  EXPECT_EQ(p->unit.programs[0].blocks.size(), 3u);
  EXPECT_EQ(p->unit.programs[0].blocks[0].seq, 10);
  EXPECT_EQ(p->unit.programs[0].blocks[0].line, 3);
  EXPECT_EQ(p->unit.programs[1].number, 2000);
}

TEST(Parser, AnonymousMainAndNamedProgram) {
  auto p = parse("G00 X1.\n<PART_A>\nM99\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  ASSERT_EQ(p->unit.programs.size(), 2u);
  EXPECT_EQ(p->unit.programs[0].name, "MAIN");
  EXPECT_EQ(p->unit.programs[1].name, "<PART_A>");
}

TEST(Parser, AndBindsLikeMultiplication) {
  // #1 + #2 AND #3 is #1 + [#2 AND #3] (spec §3.2).
  auto p = parse("#4 = #1 + #2 AND #3\n");
  const Expr& e = *firstStmt(*p).value;
  ASSERT_EQ(e.kind, ExprKind::Binary);
  EXPECT_EQ(e.binOp, BinOp::Add);
  EXPECT_EQ(e.args[1]->binOp, BinOp::And);
}

TEST(Parser, OrBindsLikeAddition) {
  auto p = parse("#4 = #1 OR #2 * #3\n");
  const Expr& e = *firstStmt(*p).value;
  EXPECT_EQ(e.binOp, BinOp::Or);
  EXPECT_EQ(e.args[1]->binOp, BinOp::Mul);
}

TEST(Parser, SpacesAndKeywordsWithoutSpaces) {
  auto p = parse("IF[#1EQ0]GOTO10\nN10 WHILE [#2 LT 3] DO 1\nEND 1\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  EXPECT_EQ(firstStmt(*p).kind, StmtKind::IfGoto);
  EXPECT_EQ(firstStmt(*p).gotoBlock, 1);
}

// ,C ,R ,A: a comma word is its lower-case letter, its range from the
// comma; it may stand alone after N (a direct drawing line's angle).
TEST(Parser, CommaWords) {
  auto p = parse("G01X40.,C2.F300.\nN10,A150.,R#1\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  const auto& b = p->unit.programs[0].blocks;
  ASSERT_EQ(b[0].stmt.words.size(), 4u);
  EXPECT_EQ(b[0].stmt.words[2].letter, 'c');
  EXPECT_EQ(b[0].stmt.words[2].range.begin.offset, 7u);
  EXPECT_EQ(b[0].stmt.words[2].range.length, 4u);
  EXPECT_EQ(b[0].stmt.words[3].letter, 'F');
  ASSERT_EQ(b[1].stmt.words.size(), 3u); // N10 first
  EXPECT_EQ(b[1].stmt.words[1].letter, 'a');
  EXPECT_EQ(b[1].stmt.words[2].letter, 'r');
  EXPECT_TRUE(b[1].stmt.words[2].bareVariable);
}

TEST(Parser, AtanForms) {
  auto p = parse("#1=ATAN[1]/[2]\n#2=ATAN[1,2]\n#3=ATAN[1]/2\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  const auto& b = p->unit.programs[0].blocks;
  EXPECT_EQ(b[0].stmt.value->builtin, Builtin::Atan2);
  EXPECT_EQ(b[1].stmt.value->builtin, Builtin::Atan2);
  EXPECT_EQ(b[2].stmt.value->kind, ExprKind::Binary); // a division
}

TEST(Parser, WordKindsAndVacantDrop) {
  auto p = parse("G01 X10 Y10. Z#1 A-#2 B[#3] F100.\n");
  const auto& w = firstStmt(*p).words;
  ASSERT_EQ(w.size(), 7u);
  EXPECT_EQ(w[1].kind, WordKind::IntLiteral);
  EXPECT_EQ(w[2].kind, WordKind::DecLiteral);
  EXPECT_TRUE(w[3].bareVariable);
  EXPECT_TRUE(w[4].bareVariable);
  EXPECT_FALSE(w[5].bareVariable);
}

TEST(Parser, MacroCallArguments) {
  auto p = parse("G65 P9100 L2 A1. X#5\n");
  const Stmt& s = firstStmt(*p);
  ASSERT_EQ(s.kind, StmtKind::MacroCall);
  ASSERT_TRUE(s.program && s.repeat);
  EXPECT_EQ(s.words.size(), 2u);
}

TEST(Parser, CommentBecomesAlarmMessage) {
  auto p = parse("IF [#24 EQ #0] THEN #3000 = 1 (X IS MISSING)\n");
  EXPECT_EQ(firstStmt(*p).message, "X IS MISSING");
}

TEST(Parser, DprntItems) {
  auto p = parse("DPRNT[X#2[53]*Y#[100+#1][20]]\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  const auto& items = firstStmt(*p).items;
  ASSERT_EQ(items.size(), 4u);
  EXPECT_EQ(items[0].text, "X");
  EXPECT_EQ(items[1].intDigits, 5);
  EXPECT_EQ(items[1].fracDigits, 3);
  EXPECT_EQ(items[2].text, "*Y");
  EXPECT_EQ(items[3].value->kind, ExprKind::Indirect);
}

TEST(Parser, SemicolonEndsTheBlock) {
  auto p = parse("#1 = 10.; #2 = 3 this is a comment\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  EXPECT_EQ(p->unit.programs[0].blocks.size(), 1u);
}

TEST(Diagnostics, UnicodeDashHasFixIt) {
  auto p = parse("#1 = #2 \xE2\x80\x93 #3\n");
  EXPECT_EQ(p->text,
            "t.nc:1:9: error: '\xE2\x80\x93' is not the minus sign; Macro B "
            "uses the ASCII '-'\n#1 = #2 \xE2\x80\x93 #3\n        ^\n"
            "        -\n");
}

TEST(Diagnostics, EveryErrorOfAFileIsReported) {
  auto p = parse("#1=[2\n#2=#3+-4\nZ = 1\nIF [#1 GT 0] THEN M99\n");
  EXPECT_EQ(p->diags.errorCount(), 4) << p->text;
}

TEST(Diagnostics, TenThousandNestedBracketsDoNotCrash) {
  std::string deep = "#1=" + std::string(10000, '[') + "1" +
                     std::string(10000, ']') + "\n#2=3\n";
  auto p = parse(deep);
  EXPECT_GE(p->diags.errorCount(), 1);
  EXPECT_NE(p->text.find("PS0118"), std::string::npos);
  EXPECT_EQ(p->unit.programs.size(), 1u); // #2=3 still parsed
}

TEST(Sema, LoopsMatchAndCrossingIsAnError) {
  auto ok = parse("WHILE[#1LT2]DO1\nWHILE[#2LT2]DO2\nEND2\nEND1\n");
  EXPECT_EQ(ok->diags.errorCount(), 0) << ok->text;
  EXPECT_EQ(firstStmt(*ok).match, 3);
  auto bad = parse("WHILE[#1LT2]DO1\nWHILE[#2LT2]DO2\nEND1\nEND2\n");
  EXPECT_NE(bad->text.find("loops may nest but not cross"), std::string::npos);
}

TEST(Sema, GotoSearchesForwardThenFromTheTop) {
  auto p = parse("N5 #1=1\nGOTO 5\nN5 #1=2\nGOTO 5\n");
  const auto& b = p->unit.programs[0].blocks;
  EXPECT_EQ(b[1].stmt.gotoBlock, 2);
  EXPECT_EQ(b[3].stmt.gotoBlock, 0);
  EXPECT_EQ(p->diags.warningCount(), 1);
}

// The index of labels against the search written out: the first block
// with the N after `from` to the end, else from the top, `from` itself
// last; every N and every `from` of programs with repeated labels.
TEST(Sema, SequenceIndexSearchesAsTheControlDoes) {
  std::uint32_t state = 7;
  const auto next = [&state](std::uint32_t below) {
    state = state * 1103515245u + 12345u;
    return (state >> 16) % below;
  };
  for (int round = 0; round < 50; ++round) {
    Program program;
    const auto size = static_cast<int>(1 + next(40));
    for (int i = 0; i < size; ++i) {
      program.blocks.emplace_back().seq =
          next(3) == 0 ? -1 : static_cast<int>(next(6));
    }
    const SequenceIndex index(program);
    for (int seq = -1; seq <= 7; ++seq) {
      for (int from = -1; from < size; ++from) {
        int expected = -1;
        for (int k = 1; k <= size && expected < 0; ++k) {
          const int i = (from + k) % size;
          expected =
              program.blocks[static_cast<std::size_t>(i)].seq == seq && seq >= 0
                  ? i
                  : -1;
        }
        EXPECT_EQ(index.find(seq, from), expected)
            << "N" << seq << " from " << from << " of " << size;
      }
    }
  }
}

TEST(Sema, GotoIntoLoopIsAnError) {
  auto p = parse("GOTO 7\nWHILE [#1 LT 2] DO1\nN7 #1=#1+1\nEND1\n");
  EXPECT_NE(p->text.find("jumps into a WHILE loop"), std::string::npos);
}

TEST(Sema, WritesToReadOnlyVariables) {
  auto p = parse("#0=1\n#5021=1\n#3011=1\n#5221=1\n");
  EXPECT_EQ(p->diags.errorCount(), 3) << p->text;
}

// Past the error limit nothing is stored, notes included: before, every
// "DO1 is already open" note of thousands of nested loops piled up on the
// "too many errors" diagnostic (and each WHILE named every open DO1).
TEST(Sema, NestedLoopErrorsStopAtTheLimitWithoutStrayNotes) {
  std::string src = "O1\n";
  for (int i = 0; i < 80; ++i) {
    src += "WHILE [1 EQ 1] DO1\n";
  }
  for (int i = 0; i < 80; ++i) {
    src += "END1\n";
  }
  auto p = parse(src + "M30\n");
  const auto& diags = p->diags.diagnostics();
  ASSERT_FALSE(diags.empty());
  EXPECT_EQ(diags.back().kind, DiagKind::TooManyErrors);
  EXPECT_TRUE(diags.back().notes.empty()) << p->text;
  for (const Diagnostic& d : diags) {
    if (d.kind == DiagKind::LoopIdReused) {
      EXPECT_EQ(d.notes.size(), 1u) << p->text;
    }
  }
}

// Named programs get numbers above the O numbers, in definition order, and
// each call by name its program's number; a name nothing defines makes its
// block raise PS0310.
TEST(Sema, CallsByNameGetTheirProgramsNumbers) {
  auto p = parse("O80000001\nM98<FACE>L2\nG65<BORE>D30.\nG66<PECK>Z-5.\n"
                 "M98<GONE>\nM30\n<BORE>\nM99\n<FACE>\nM99\n");
  ASSERT_EQ(p->diags.errorCount(), 0) << p->text;
  const auto& programs = p->unit.programs;
  ASSERT_EQ(programs.size(), 3u);
  EXPECT_EQ(programs[1].number, kFirstNamedProgram);
  EXPECT_EQ(programs[2].number, kFirstNamedProgram + 1);
  const auto& b = programs[0].blocks;
  const Word& face = b[0].stmt.words.at(1);
  EXPECT_EQ(face.letter, 'P');
  EXPECT_EQ(face.calledName, "<FACE>");
  EXPECT_EQ(face.value->number, kFirstNamedProgram + 1);
  ASSERT_EQ(b[1].stmt.kind, StmtKind::MacroCall);
  EXPECT_EQ(b[1].stmt.program->number, kFirstNamedProgram);
  EXPECT_EQ(b[1].alarm, AlarmId::None);
  EXPECT_EQ(b[2].alarm, AlarmId::FileNotFound); // <PECK>
  EXPECT_EQ(b[3].alarm, AlarmId::FileNotFound); // <GONE>
  EXPECT_EQ(b[3].alarmDetail, "<GONE>");
  EXPECT_EQ(p->diags.warningCount(), 2) << p->text;
}

// On a lathe, mbc check notes a G71/G72 whose shape's first block gives
// the cut axis too (type II): its path is reconstructed (docs/language.md).
TEST(Sema, NotesTypeTwoRoughing) {
  const auto notes = [](const std::string& src) {
    Parsed p;
    const std::uint32_t id = p.sources.add("t.nc", src);
    ParseOptions o;
    o.latheSystem = 'A';
    parseFile(p.sources, id, p.diags, o, p.unit);
    checkUnit(p.unit, p.diags, SemaOptions{true, 'A', true});
    int count = 0;
    for (const Diagnostic& d : p.diags.diagnostics()) {
      count += d.kind == DiagKind::TypeTwoRoughing ? 1 : 0;
    }
    return count;
  };
  EXPECT_EQ(notes("G71U1.R0.5\nG71P10Q20F0.2\nN10G00X20.W0\nN20G01Z-5.\n"), 1);
  EXPECT_EQ(notes("G72W1.R0.5\nG72P10Q20F0.2\nN10G00X20.Z-5.\nN20X10.\n"), 1);
  EXPECT_EQ(notes("G71U1.R0.5\nG71P10Q20F0.2\nN10G00X20.\nN20G01Z-5.\n"), 0);
}

} // namespace
} // namespace mbc
