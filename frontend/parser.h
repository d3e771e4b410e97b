// Recursive-descent parser for Custom Macro B. One block per line; an error
// is reported and the parser resynchronises at the end of the block, so one
// run reports every error of a file.
#pragma once

#include "frontend/ast.h"
#include "frontend/lexer.h"

#include <deque>
#include <optional>

namespace mbc {

struct ParseOptions {
  /// `mbc check`: also report the warnings that only a review needs
  /// (whole-number literals on axes, ...).
  bool checkWarnings = false;
  /// The control's bracket nesting limit, function brackets included.
  int maxBracketDepth = 5;
  /// Stop reading at the error limit (mbc check); `mbc run` reads on, since
  /// every block it cannot read becomes an alarm.
  bool stopAtErrorLimit = true;
  /// A lathe's G code system ('A', 'B', 'C'), 0 on a machining centre:
  /// which G codes mbc check reports and which words of them are lengths.
  char latheSystem = 0;
  /// The unit at power-on (the profile's): inch input reads a literal
  /// without decimal point in 0.0001 inch. G20/G21 change it from their
  /// block on, in the order of the text.
  bool inch = false;
  /// Parameter 3401#0 DPI: a literal without decimal point is in whole mm
  /// or inches, so none is worth a warning.
  bool decimalPointInput = false;
};

/// Parses one file and appends its programs to unit.
void parseFile(const SourceManager& sources, std::uint32_t file,
               DiagnosticEngine& diags, const ParseOptions& options,
               Unit& unit);

namespace detail {

/// Thrown after a diagnostic to abandon the current block.
struct BlockError {};

class Parser {
public:
  Parser(const SourceManager& sources, std::uint32_t file,
         DiagnosticEngine& diags, const ParseOptions& options, Unit& unit);
  void run();

private:
  // Blocks and statements (parse_block.cpp, parse_stmt.cpp).
  void parseBlock();
  bool parseProgramHeader();
  void parseStatement(Block& b);
  void parseAssign(Stmt& s);
  void parseIf(Stmt& s);
  void parseGoto(Stmt& s);
  void parseWhile(Stmt& s);
  void parseDoEnd(Stmt& s, bool isEnd);
  int parseLoopNumber(const Token& keyword);
  ExprPtr parseBracketCondition(const Token& keyword);
  void parseWords(Stmt& s);
  Word parseWord();
  bool atCommaWord();
  Word parseCommaWord();
  Word parseCalledName(const Stmt& s);
  void finishMacroCall(Stmt& s);
  void reportUnmodelledCodes(const std::vector<Word>& words);

  // What a block's G codes make of its letters (checkDecimalPoint).
  struct WordUnits {
    std::string notLengths; // no length: no warning
    std::string angles;     // degrees
    // Numbers and counts: a decimal point is PS0007 (G51's P is none).
    std::string counts = "PL";
    bool dwell = false; // G04: X and U count milliseconds
  };

  void refuseCallNumberPoint(const Word& w);
  void checkDecimalPoint(const Word& w, bool macroArgument,
                         const WordUnits& units);
  void parsePrint(Stmt& s);
  PrintItem parsePrintVariable(const std::string& statement);
  void expectEndOfBlock(const Stmt& s);
  void rejectExponent();
  [[noreturn]] void misplacedHeader();
  void resynchronise();
  void keepBrokenBlock(Block& b);
  void reportThenWithoutAssignment(const Token& then);
  void addSequenceWord(Block& b, SourceRange range);
  void splitLeadCodes(Block& b, SourceRange seqRange);
  void takeAlarm(Block& b);
  void pushBlock(Block& b);
  void noteParenthesis(const Token& after);
  std::string sourceText(SourceRange r) const;
  /// The stray text (ASSY, OP 10 ROUGH) that starts at an address without
  /// a value: three letters in a row, up to the end of the line, or the
  /// word alone before a comment; none for a plain missing value.
  std::optional<SourceRange> strayText(const Token& letter) const;
  void refuseUnsupportedFunction(const Token& letter);
  bool startsParameterRead(const Token& letter) const;
  ExprPtr parseParameterRead(int depth);
  void reportUnsupportedDataInput(const Word& g10,
                                  const std::vector<Word>& words);
  std::uint32_t parseArguments(int depth, Expr& e);
  const Token* messageAfter(std::uint32_t offset) const;
  void checkMessageLength(const Stmt& s, const Token& comment);
  Program& currentProgram(SourceLoc at);

  // Expressions (parse_expr.cpp).
  ExprPtr parseExpr(int depth);
  ExprPtr parseSum(int depth, bool allowSign);
  ExprPtr parseTerm(int depth, bool allowSign);
  ExprPtr parseUnary(int depth, bool allowSign);
  ExprPtr parsePrimary(int depth);
  ExprPtr parseBracketed(int depth);
  ExprPtr parseVariable(int depth);
  ExprPtr parseCall(int depth);
  ExprPtr makeBinary(const Token& op, ExprPtr lhs, ExprPtr rhs);
  void enterBracket(int depth, const Token& at);
  [[noreturn]] void addressInExpression(const Token& t);
  void requireNumber(const Expr& e);

  // Tokens.
  void advance();
  const Token& peek();

  bool isKeyword(Keyword k) const {
    return tok_.kind == Tok::Keyword && tok_.keyword == k;
  }

  [[noreturn]] void fail();
  [[noreturn]] void unexpected(DiagKind kind);

  const SourceManager& sources_;
  std::uint32_t file_;
  DiagnosticEngine& diags_;
  ParseOptions options_;
  Unit& unit_;
  Lexer lexer_;
  Token tok_;
  Token previous_; // the token before tok_
  std::deque<Token> ahead_;
  std::vector<Token> blockComments_;
  int program_ = -1;            // index in unit_.programs
  bool inch_ = false;           // G20 in force at this point of the text
  bool parameterInput_ = false; // between G10 L52 and G11
  bool reportedDepth_ = false;
  bool macroStatement_ = false; // the block's statement starts with # or a
                                // keyword
  int operands_ = 0;
};

} // namespace detail
} // namespace mbc
