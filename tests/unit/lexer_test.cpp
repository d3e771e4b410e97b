// The lexer: keywords against address letters, spaces, comments, numbers and
// the print mode of DPRNT.
#include "frontend/lexer.h"

#include <gtest/gtest.h>

namespace mbc {
namespace {

std::vector<Token> lex(const std::string& text) {
  static SourceManager sources;
  static DiagnosticEngine diags(sources);
  std::uint32_t id = sources.add("t.nc", text);
  Lexer lexer(sources, id, diags);
  std::vector<Token> out;
  for (Token t = lexer.next(); t.kind != Tok::EndOfFile; t = lexer.next()) {
    out.push_back(t);
  }
  return out;
}

std::string kinds(const std::vector<Token>& tokens) {
  std::string s;
  for (const Token& t : tokens) {
    s += t.kind == Tok::Letter       ? "L" + t.text
         : t.kind == Tok::Keyword    ? "K" + t.text
         : t.kind == Tok::Function   ? "F" + t.text
         : t.kind == Tok::Number     ? "N" + t.text
         : t.kind == Tok::Hash       ? std::string("#")
         : t.kind == Tok::EndOfBlock ? std::string(";")
                                     : std::string("?");
    s += ' ';
  }
  return s;
}

TEST(Lexer, KeywordsWithoutSpaces) {
  EXPECT_EQ(kinds(lex("IF[#1EQ0]GOTO10\n")),
            "KIF ? # N1 KEQ N0 ? KGOTO N10 ; ");
}

TEST(Lexer, AddressLettersBeforeDigits) {
  EXPECT_EQ(kinds(lex("G01X10.Y-2F#9\n")), "LG N01 LX N10. LY ? N2 LF # N9 ; ");
}

TEST(Lexer, LongestKeywordWins) {
  EXPECT_EQ(kinds(lex("#1=ATAN[1]+ASIN[1]XOR#2\n")),
            "# N1 ? FATAN ? N1 ? ? FASIN ? N1 ? KXOR # N2 ; ");
  EXPECT_EQ(kinds(lex("END1\nDO2\n")), "KEND N1 ; KDO N2 ; ");
}

// Macro B has no exponent notation: a number followed by E is the next
// word, as CAM posts pack them.
TEST(Lexer, LetterAfterNumberIsTheNextWord) {
  EXPECT_EQ(kinds(lex("F800E41V0.2E41\n")), "LF N800 LE N41 LV N0.2 LE N41 ; ");
}

// Two letters in a row are the control's abbreviation of a macro word; PO
// is POW before its bracket and POPEN alone.
TEST(Lexer, TwoLetterAbbreviations) {
  EXPECT_EQ(kinds(lex("WH[#1LT5]DO1\nEN1\nGO10\n")),
            "KWHILE ? # N1 KLT N5 ? KDO N1 ; KEND N1 ; KGOTO N10 ; ");
  EXPECT_EQ(kinds(lex("#1=PO[2,3]\nPO\n")),
            "# N1 ? FPOW ? N2 ? N3 ? ; KPOPEN ; ");
  EXPECT_EQ(kinds(lex("XY\n")), "LX LY ; ");
}

TEST(Lexer, SpacesInsideNumbers) {
  auto t = lex("X1 00.5\n");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].number, 100.5);
  EXPECT_TRUE(t[1].hasDecimal);
}

TEST(Lexer, LowerCaseReadsAsUpperCase) {
  EXPECT_EQ(kinds(lex("g01 x1.\n")), "LG N01 LX N1. ; ");
}

TEST(Lexer, SemicolonEndsTheBlockAndCommentsAreTokens) {
  auto t = lex("#1=2 (NOTE) ; rest is comment #2=3\n#3=4\n");
  EXPECT_EQ(t[4].kind, Tok::Comment);
  EXPECT_EQ(t[4].text, "NOTE");
  EXPECT_EQ(kinds(t), "# N1 ? N2 ? ; # N3 ? N4 ; ");
}

TEST(Lexer, CrLfAndLoneCrEndBlocks) {
  EXPECT_EQ(kinds(lex("#1=1\r\n#2=2\r#3=3")),
            "# N1 ? N1 ; # N2 ? N2 ; # N3 ? N3 ");
}

TEST(Lexer, PercentMarksTheProgramText) {
  EXPECT_EQ(kinds(lex("leader\n%\n#1=1\n%\n#2=2\n")), "; # N1 ? N1 ; ");
  EXPECT_EQ(kinds(lex("#1=1 (50% DONE)\n%\n")), "# N1 ? N1 ? ; ");
  // The '%' line ends at a lone CR as at LF (old Mac files).
  EXPECT_EQ(kinds(lex("%\r#1=1\r%\r")), "; # N1 ? N1 ; ");
}

} // namespace
} // namespace mbc
