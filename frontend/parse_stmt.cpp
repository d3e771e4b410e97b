// Statements: assignments, IF/GOTO/THEN, WHILE/DO/END, NC words and G65
// calls. Macro B's classic mistakes get a diagnostic with the fix.
#include "frontend/parser.h"
#include <mbc/addresses.h>
#include <mbc/alarm.h>
#include <mbc/calling_codes.h>
#include <mbc/g_codes.h>
#include <mbc/limits.h>

#include <algorithm>
#include <cmath>

namespace mbc::detail {

namespace {

// Addresses whose whole-number literals are in least-increment units.
bool isLengthAddress(char c) {
  return std::string_view("XYZABCUVWIJKRQ").find(c) != std::string_view::npos;
}

} // namespace

void Parser::parseStatement(Block& b) {
  Stmt& s = b.stmt;
  s.range.begin = tok_.range.begin;
  macroStatement_ = tok_.kind == Tok::Hash || tok_.kind == Tok::Keyword;
  switch (tok_.kind) {
    case Tok::EndOfBlock:
    case Tok::EndOfFile:
      return;
    case Tok::Hash:
      parseAssign(s);
      return;
    case Tok::Letter:
      if (tok_.text == "O" || tok_.text == "N") {
        misplacedHeader();
      }
      parseWords(s);
      return;
    case Tok::Keyword:
      break;
    case Tok::Comma: // N10,A150.: a direct drawing line of an angle alone
      if (atCommaWord()) {
        parseWords(s);
        return;
      }
      [[fallthrough]];
    default:
      unexpected(DiagKind::UnexpectedToken);
  }
  switch (tok_.keyword) {
    case Keyword::If:
      parseIf(s);
      return;
    case Keyword::Goto:
      parseGoto(s);
      return;
    case Keyword::While:
      parseWhile(s);
      return;
    case Keyword::Do:
      parseDoEnd(s, false);
      return;
    case Keyword::End:
      parseDoEnd(s, true);
      return;
    case Keyword::Dprnt:
    case Keyword::Bprnt:
      parsePrint(s);
      return;
    case Keyword::Popen:
    case Keyword::Pclos:
      s.kind =
          tok_.keyword == Keyword::Popen ? StmtKind::Popen : StmtKind::Pclos;
      advance();
      return;
    default:
      unexpected(DiagKind::UnexpectedToken);
  }
}

void Parser::misplacedHeader() {
  diags_.report(tok_.text == "O" ? DiagKind::OInsideBlock
                                 : DiagKind::SequenceInsideBlock,
                tok_.range);
  fail();
}

// assignment := '#' (number | '[' expr ']') '=' expr
void Parser::parseAssign(Stmt& s) {
  ExprPtr target = parseVariable(0);
  if (s.kind != StmtKind::IfThen) {
    s.kind = StmtKind::Assign;
  }
  s.target.range = target->range;
  if (target->kind == ExprKind::Var) {
    s.target.number = target->var;
  } else {
    s.target.index = std::move(target->args[0]);
  }
  if (tok_.kind != Tok::Equal) {
    diags_.report(DiagKind::ExpectedEqual, tok_.range);
    fail();
  }
  std::uint32_t eq = tok_.range.begin.offset;
  advance();
  s.value = parseExpr(0);
  requireNumber(*s.value);
  if (const Token* comment = messageAfter(eq)) {
    s.message = comment->text;
    checkMessageLength(s, *comment);
  }
}

// #3000 and #3006 show a part of their message (as the runtime does); a
// longer one loses its end unnoticed.
void Parser::checkMessageLength(const Stmt& s, const Token& comment) {
  if (!options_.checkWarnings || s.target.index ||
      (s.target.number != 3000 && s.target.number != 3006)) {
    return;
  }
  const std::string_view text = trimmedMessage(s.message);
  if (text.size() > kMessageShown) {
    diags_.report(DiagKind::MessageTooLong, comment.range, s.target.number,
                  kMessageShown, std::string(text.substr(0, kMessageShown)));
  }
}

// Reads '[' cond ']' and, for the seed-003 form `[a] OR [b]`, the rest of an
// unbracketed compound condition, with a fix-it adding the outer brackets.
ExprPtr Parser::parseBracketCondition(const Token& keyword) {
  if (tok_.kind != Tok::LBracket) {
    diags_.report(DiagKind::IfNeedsBracket, tok_.range, keyword.text)
        .fixIts.push_back({{tok_.range.begin, 0}, "["});
    fail();
  }
  Token first = tok_;
  ExprPtr cond = parsePrimary(0);
  Token lastClose = tok_;
  bool compound = false;
  while (tok_.kind == Tok::Keyword &&
         (tok_.keyword == Keyword::And || tok_.keyword == Keyword::Or ||
          tok_.keyword == Keyword::Xor)) {
    compound = true;
    Token op = tok_;
    advance();
    if (tok_.kind != Tok::LBracket) {
      unexpected(DiagKind::ExpectedExpression);
    }
    ExprPtr rhs = parsePrimary(1);
    cond = makeBinary(op, std::move(cond), std::move(rhs));
    lastClose = tok_;
  }
  if (compound) {
    SourceRange span{first.range.begin,
                     lastClose.range.begin.offset - first.range.begin.offset};
    while (span.length > 0 &&
           sources_.text(file_)[span.begin.offset + span.length - 1] == ' ') {
      --span.length;
    }
    auto& d = diags_.report(DiagKind::CompoundNeedsBrackets, span);
    d.fixIts.push_back({span, fmt::format("[{}]", sourceText(span))});
  }
  if (!cond->isCondition()) {
    diags_.report(DiagKind::NumberAsCondition, cond->range);
    fail();
  }
  return cond;
}

// if := 'IF' '[' cond ']' ('GOTO' expr | 'THEN' assignment)
void Parser::parseIf(Stmt& s) {
  Token kw = tok_;
  advance();
  s.cond = parseBracketCondition(kw);
  if (isKeyword(Keyword::Goto)) {
    s.kind = StmtKind::IfGoto;
    advance();
    s.value = parseSum(0, true);
    requireNumber(*s.value);
    return;
  }
  if (isKeyword(Keyword::Then)) {
    Token then = tok_;
    advance();
    if (tok_.kind == Tok::Hash) {
      s.kind = StmtKind::IfThen;
      parseAssign(s);
      return;
    }
    reportThenWithoutAssignment(then);
    fail();
  }
  diags_.report(DiagKind::ExpectedGotoOrThen, tok_.range);
  fail();
}

// What follows THEN is no assignment: say what it is and how to write it.
void Parser::reportThenWithoutAssignment(const Token& then) {
  if (tok_.kind == Tok::Letter) {
    diags_.report(DiagKind::ThenNeedsMacroStatement, tok_.range, "NC words");
    diags_.note(DiagKind::ThenNcNote, tok_.range);
  } else if (isKeyword(Keyword::Goto)) {
    auto& d =
        diags_.report(DiagKind::ThenNeedsMacroStatement, tok_.range, "GOTO");
    d.fixIts.push_back(
        {{then.range.begin, tok_.range.begin.offset + tok_.range.length -
                                then.range.begin.offset},
         "GOTO"});
    diags_.note(DiagKind::ThenGotoNote, tok_.range);
  } else if (tok_.kind == Tok::Keyword) {
    diags_.report(DiagKind::ThenNeedsMacroStatement, tok_.range, tok_.text);
    diags_.note(DiagKind::ThenStatementNote, tok_.range, tok_.text);
  } else if (tok_.kind == Tok::EndOfBlock || tok_.kind == Tok::EndOfFile) {
    diags_.report(DiagKind::ThenNeedsMacroStatement, then.range,
                  "the end of the block");
  } else {
    diags_.report(DiagKind::ThenNeedsMacroStatement, tok_.range,
                  fmt::format("'{}'", tok_.text));
  }
}

// goto := 'GOTO' expr
void Parser::parseGoto(Stmt& s) {
  s.kind = StmtKind::Goto;
  advance();
  s.value = parseSum(0, true);
  requireNumber(*s.value);
}

int Parser::parseLoopNumber(const Token& keyword) {
  if (tok_.kind != Tok::Number || tok_.hasDecimal) {
    diags_.report(DiagKind::LoopNumberMissing, tok_.range, keyword.text);
    fail();
  }
  int id = tok_.number > 99 ? 99 : static_cast<int>(tok_.number);
  if (id < 1 || id > kMaxLoopNumber) {
    diags_.report(DiagKind::LoopNumberRange, tok_.range, tok_.text);
  }
  advance();
  return id;
}

// while := 'WHILE' '[' cond ']' 'DO' m
void Parser::parseWhile(Stmt& s) {
  Token kw = tok_;
  advance();
  s.cond = parseBracketCondition(kw);
  if (!isKeyword(Keyword::Do)) {
    diags_.report(DiagKind::ExpectedDo, tok_.range);
    fail();
  }
  Token doTok = tok_;
  advance();
  s.kind = StmtKind::While;
  s.loopId = parseLoopNumber(doTok);
}

// do := 'DO' m   (a loop without condition: leave it with GOTO)
// end := 'END' m
void Parser::parseDoEnd(Stmt& s, bool isEnd) {
  Token kw = tok_;
  advance();
  s.kind = isEnd ? StmtKind::End : StmtKind::While;
  s.loopId = parseLoopNumber(kw);
}

// word := letter (['+'|'-'] (number | '#' var | '[' expr ']'))
Word Parser::parseWord() {
  Word w;
  Token letter = tok_;
  w.letter = letter.text[0];
  advance();
  if (tok_.kind == Tok::Equal) {
    // `Z = #101 + 0.03` (seed 003): the author meant Z[#101 + 0.03].
    Token eq = tok_;
    advance();
    std::uint32_t valueStart = tok_.range.begin.offset;
    w.value = parseExpr(0);
    std::uint32_t valueEnd =
        w.value->range.begin.offset + w.value->range.length;
    SourceRange span{eq.range.begin, valueEnd - eq.range.begin.offset};
    SourceRange value{{file_, valueStart}, valueEnd - valueStart};
    auto& d = diags_.report(DiagKind::AssignToAddress, eq.range, letter.text);
    d.fixIts.push_back({span, fmt::format("[{}]", sourceText(value))});
    diags_.note(DiagKind::AssignToAddressNote, letter.range, letter.text);
    return w;
  }
  bool negative = false;
  Token sign = tok_;
  if (tok_.kind == Tok::Minus || tok_.kind == Tok::Plus) {
    negative = tok_.kind == Tok::Minus;
    advance();
  }
  switch (tok_.kind) {
    case Tok::Number: {
      auto e = std::make_unique<Expr>();
      e->kind = ExprKind::Number;
      e->range = tok_.range;
      e->number = negative && tok_.number != 0 ? -tok_.number : tok_.number;
      e->hasDecimal = tok_.hasDecimal;
      w.kind = tok_.hasDecimal ? WordKind::DecLiteral : WordKind::IntLiteral;
      w.value = std::move(e);
      advance();
      break;
    }
    case Tok::Hash:
      w.value = parseVariable(0);
      w.bareVariable = true;
      break;
    case Tok::LBracket:
      w.value = parseBracketed(0);
      break;
    case Tok::Function:
      diags_.report(DiagKind::FunctionInAddress, tok_.range, letter.text,
                    tok_.text);
      w.value = parseCall(1);
      break;
    default:
      refuseUnsupportedFunction(letter);
      if (const std::optional<SourceRange> text = strayText(letter)) {
        const std::string written = sourceText(*text);
        diags_.report(DiagKind::StrayText, *text, written)
            .fixIts.push_back({*text, fmt::format("({})", written)});
        fail();
      }
      diags_.report(DiagKind::ExpectedAddressValue, letter.range, letter.text);
      noteParenthesis(letter);
      fail();
  }
  requireNumber(*w.value);
  if (negative && w.kind == WordKind::Value) {
    auto neg = std::make_unique<Expr>();
    neg->kind = ExprKind::Neg;
    neg->range = {sign.range.begin, 0};
    neg->args.push_back(std::move(w.value));
    w.value = std::move(neg);
  }
  w.range = {letter.range.begin, w.value->range.begin.offset +
                                     w.value->range.length -
                                     letter.range.begin.offset};
  return w;
}

bool Parser::atCommaWord() {
  if (tok_.kind != Tok::Comma) {
    return false;
  }
  const Token& letter = peek();
  return letter.kind == Tok::Letter &&
         (letter.text == "C" || letter.text == "R" || letter.text == "A");
}

// comma word := ',' ('C' | 'R' | 'A') value: chamfer, corner R, angle
Word Parser::parseCommaWord() {
  const SourceLoc comma = tok_.range.begin;
  advance();
  Word w = parseWord();
  w.letter = commaWordLetter(w.letter);
  w.range = {comma, w.range.begin.offset + w.range.length - comma.offset};
  return w;
}

// nc := (word | comma word)+   (G65 among the words makes it a macro call)
void Parser::parseWords(Stmt& s) {
  s.kind = StmtKind::Nc;
  while (tok_.kind == Tok::Letter || atCommaWord()) {
    if (tok_.kind == Tok::Comma) {
      s.words.push_back(parseCommaWord());
      continue;
    }
    if (tok_.text == "O" || tok_.text == "N") {
      misplacedHeader();
    }
    s.words.push_back(parseWord());
    if (tok_.kind == Tok::ProgramName) {
      s.words.push_back(parseCalledName(s));
    }
  }
  const auto literal = [&](char letter, double value) {
    return std::any_of(s.words.begin(), s.words.end(), [&](const Word& w) {
      return w.letter == letter && w.value->kind == ExprKind::Number &&
             w.value->number == value;
    });
  };
  // G10 L52 ... G11: the blocks between are parameter data, N the number
  // and R the value, which no length or sequence number rule reads.
  if (parameterInput_) {
    s.parameterData = true;
    parameterInput_ = !literal('G', 11);
    return;
  }
  parameterInput_ = literal('G', 10) && (literal('L', 52) || literal('L', 50));
  reportUnmodelledCodes(s.words);
  for (const Word& w : s.words) {
    if (w.letter == 'G' && w.value->kind == ExprKind::Number &&
        w.value->number == 65) {
      finishMacroCall(s);
      return;
    }
  }
  // Letters whose literal is no length in this block: G04's X (ms), a
  // cycle's K (repeats), G51's I J K (scale factors), the switches of
  // G05.1 and G05.4 (Q1, R level), M98's Q (a sequence number); G68's R is
  // an angle.
  WordUnits units;
  for (const Word& w : s.words) {
    if (w.letter == 'M' && w.value->kind == ExprKind::Number &&
        isSubprogramCall('M', w.value->number)) {
      units.notLengths += 'Q';
    }
    if (w.letter != 'G' || w.value->kind != ExprKind::Number) {
      continue;
    }
    const double g = w.value->number;
    if (options_.latheSystem != 0) {
      // A lathe's cycles take sequence numbers, counts and increments;
      // its G10 Q is a tip direction.
      const int a = latheFunction(options_.latheSystem,
                                  static_cast<int>(std::round(g * 10.0)));
      units.dwell = units.dwell || a == 40;
      inch_ = a == 200 || (inch_ && a != 210); // G20/G21 (C: G70/G71)
      units.notLengths += a >= 700 && a <= 760 ? "PQR" : a == 100 ? "Q" : "";
      continue;
    }
    units.dwell = units.dwell || g == 4;
    inch_ = g == 20 || (inch_ && g != 21);
    if (g == 73 || g == 74 || g == 76 || (g >= 81 && g <= 89)) {
      units.notLengths += 'K';
    } else if (g == 51) {
      units.notLengths += "IJK";
      units.counts = "L"; // P is the magnification
    } else if (g == 5.1 || g == 5.4) {
      units.notLengths += "QR";
    } else if (g == 68) {
      units.angles += 'R';
    }
  }
  for (const Word& w : s.words) {
    checkDecimalPoint(w, false, units);
  }
}

// mbc check: a G code the runtime does not execute (the runtime's table
// decides) stops the run, so the check says so. The run itself alarms at
// the block, MBC0001 naming the code.
void Parser::reportUnmodelledCodes(const std::vector<Word>& words) {
  if (!options_.checkWarnings) {
    return;
  }
  for (const Word& w : words) {
    if (w.letter != 'G' || w.value->kind != ExprKind::Number) {
      continue;
    }
    const double tenths = std::round(w.value->number * 10.0);
    if (tenths < 0 || tenths > 9999) {
      continue;
    }
    const int code = static_cast<int>(tenths);
    const int lathe = options_.latheSystem != 0
                          ? latheFunction(options_.latheSystem, code)
                          : 0;
    if (const char* name = options_.latheSystem == 0 ? unmodelledGCode(code)
                           : lathe >= 0 ? unmodelledLatheFunction(lathe)
                                        : nullptr) {
      diags_.report(DiagKind::UnsupportedGCode, w.range, gCodeText(code), name);
    }
    if (code == 100 && options_.latheSystem == 0) {
      reportUnsupportedDataInput(w, words);
    }
  }
}

// A mill's G10 with an L the runtime does not execute (dataInputKind).
void Parser::reportUnsupportedDataInput(const Word& g10,
                                        const std::vector<Word>& words) {
  const auto l = std::find_if(words.begin(), words.end(),
                              [](const Word& w) { return w.letter == 'L'; });
  if (l == words.end()) {
    diags_.report(DiagKind::UnsupportedDataInput, g10.range, "without L");
    return;
  }
  if (l->value->kind != ExprKind::Number) {
    return; // computed: the run decides
  }
  const double value = l->value->number;
  if (value < 0 || value > 99 || value != std::floor(value) ||
      dataInputKind(static_cast<int>(value)) == nullptr) {
    diags_.report(DiagKind::UnsupportedDataInput, l->range,
                  fmt::format("L{}", value));
  }
}

// M98 <DRILL>, M198 <DRILL>, G65 <BOLT> A6., G66 <PECK>: the name in place
// of P, right after the calling code.
Word Parser::parseCalledName(const Stmt& s) {
  const Word& code = s.words.back();
  const double n =
      code.value->kind == ExprKind::Number ? code.value->number : -1.0;
  const bool calls = callsByP(code.letter, n);
  const bool hasP = std::any_of(s.words.begin(), s.words.end(),
                                [](const Word& w) { return w.letter == 'P'; });
  if (!calls || hasP) {
    diags_.report(DiagKind::MisplacedProgramName, tok_.range);
    fail();
  }
  if (tok_.text == "<>") {
    diags_.report(DiagKind::EmptyProgramName, tok_.range);
    fail();
  }
  if (tok_.text.find('/') != std::string::npos) {
    diags_.report(DiagKind::CallByPath, tok_.range, tok_.text);
    fail();
  }
  Word w;
  w.letter = 'P';
  w.kind = WordKind::IntLiteral;
  w.range = tok_.range;
  w.value = std::make_unique<Expr>();
  w.value->kind = ExprKind::Number;
  w.value->range = tok_.range;
  w.calledName = tok_.text;
  advance();
  return w;
}

void Parser::finishMacroCall(Stmt& s) {
  s.kind = StmtKind::MacroCall;
  std::vector<Word> args;
  bool seenG65 = false;
  for (Word& w : s.words) {
    if (w.letter == 'G' && !seenG65 && w.value->kind == ExprKind::Number &&
        w.value->number == 65) {
      seenG65 = true;
    } else if (w.letter == 'G' && !seenG65) {
      s.leadCodes.push_back(std::move(w));
    } else if (w.letter == 'P') {
      refuseCallNumberPoint(w);
      s.program = std::move(w.value);
      s.calledName = std::move(w.calledName);
    } else if (w.letter == 'L') {
      refuseCallNumberPoint(w);
      s.repeat = std::move(w.value);
    } else if (w.letter == 'G') {
      diags_.report(DiagKind::BadMacroArgument, w.range, "G",
                    "G is an argument only with G66.1, PS0129");
    } else if (isCommaWord(w.letter)) {
      diags_.report(DiagKind::CommaMacroArgument, w.range,
                    addressText(w.letter));
    } else {
      checkDecimalPoint(w, true, WordUnits{});
      args.push_back(std::move(w));
    }
  }
  s.words = std::move(args);
  if (!s.program) {
    diags_.report(DiagKind::G65NeedsP, s.range);
  }
}

namespace {

/// "P2" for P2.: the fix-it of a whole number written with a point, when
/// the point is all that is wrong (not beyond any number a call looks up,
/// which no integer type need hold).
void addWholeNumberFix(Diagnostic& d, const Word& w) {
  const double value = w.value->number;
  if (value == std::trunc(value) && std::fabs(value) <= kMaxCallNumber) {
    d.fixIts.push_back({w.range, fmt::format("{}{}", w.letter,
                                             static_cast<long long>(value))});
  }
}

} // namespace

// G65 P is a program number and L a count: with a decimal point the block
// is PS0007 when it runs.
void Parser::refuseCallNumberPoint(const Word& w) {
  if (w.kind == WordKind::DecLiteral) {
    addWholeNumberFix(diags_.report(DiagKind::CallNumberDecimal, w.range,
                                    std::string(1, w.letter)),
                      w);
  }
}

void Parser::checkDecimalPoint(const Word& w, bool macroArgument,
                               const WordUnits& units) {
  if (!options_.checkWarnings) {
    return;
  }
  if (!macroArgument && w.kind == WordKind::DecLiteral &&
      (isWholeNumberAddress(w.letter) ||
       units.counts.find(w.letter) != std::string::npos)) {
    addWholeNumberFix(diags_.report(DiagKind::IntegerAddressDecimal, w.range,
                                    std::string(1, w.letter)),
                      w);
    return;
  }
  if (units.dwell) {
    return; // G04 X1000 is a second
  }
  // A U V W B C are axes only on machines that have them; as macro
  // arguments on the default machine they are plain numbers.
  bool length = macroArgument
                    ? std::string_view("XYZIJKRQ").find(w.letter) !=
                          std::string_view::npos
                    : isLengthAddress(w.letter) || isCommaWord(w.letter);
  if (w.kind != WordKind::IntLiteral || w.value->number == 0 || !length ||
      units.notLengths.find(w.letter) != std::string::npos ||
      options_.decimalPointInput) {
    return;
  }
  double v = w.value->number;
  bool rotary = w.letter == 'A' || w.letter == 'B' || w.letter == 'C' ||
                w.letter == commaWordLetter('A') ||
                units.angles.find(w.letter) != std::string::npos;
  // The increment is 0.001 mm, 0.0001 inch in G20, 0.001 degree whatever
  // the unit (IS-B); trim the zeros.
  const bool inch = inch_ && !rotary;
  std::string scaled = inch ? fmt::format("{:.4f}", v * 0.0001)
                            : fmt::format("{:.3f}", v * 0.001);
  while (scaled.back() == '0') {
    scaled.pop_back();
  }
  if (scaled.back() == '.') {
    scaled.pop_back();
  }
  diags_.report(DiagKind::NoDecimalPoint, w.range, addressText(w.letter),
                fmt::format("{}", v), scaled,
                rotary ? "deg"
                : inch ? "in"
                       : "mm");
}

// print := ('DPRNT'|'BPRNT') '[' (text | '#' var '[' digits ']')* ']'
void Parser::parsePrint(Stmt& s) {
  Token kw = tok_;
  s.kind = kw.keyword == Keyword::Dprnt ? StmtKind::Dprnt : StmtKind::Bprnt;
  // Print text is lexed in its own mode, so no token may be buffered here.
  tok_ = lexer_.next();
  if (tok_.kind != Tok::LBracket) {
    diags_.report(DiagKind::PrintNeedsBracket, tok_.range, kw.text, kw.text);
    if (tok_.kind == Tok::Comment) {
      diags_.note(DiagKind::ParenthesisIsComment, tok_.range);
    }
    fail();
  }
  Token open = tok_;
  tok_ = lexer_.nextPrint();
  for (;;) {
    if (tok_.kind == Tok::PrintText || tok_.kind == Tok::Comment) {
      if (tok_.kind == Tok::Comment) {
        blockComments_.push_back(tok_);
      } else {
        PrintItem item;
        item.text = tok_.text;
        item.range = tok_.range;
        s.items.push_back(std::move(item));
      }
      tok_ = lexer_.nextPrint();
      continue;
    }
    if (tok_.kind == Tok::Hash) {
      s.items.push_back(parsePrintVariable(kw.text));
      continue;
    }
    if (tok_.kind == Tok::RBracket) {
      break;
    }
    auto& d = diags_.report(DiagKind::ExpectedCloseBracket, tok_.range);
    d.fixIts.push_back({{tok_.range.begin, 0}, "]"});
    diags_.note(DiagKind::BracketOpenedHere, open.range);
    fail();
  }
  advance();
}

// A DPRNT variable: '#' var '[' c d ']'. On return tok_ is the token after
// the format, lexed in print mode.
PrintItem Parser::parsePrintVariable(const std::string& statement) {
  PrintItem item;
  Token hash = tok_;
  item.value = parseVariable(0);
  if (tok_.kind != Tok::LBracket) {
    diags_.report(DiagKind::PrintNeedsFormat, item.value->range, statement,
                  item.value->kind == ExprKind::Var
                      ? std::to_string(item.value->var)
                      : std::string("[...]"));
    fail();
  }
  Token open = tok_;
  Token digits = lexer_.next();
  Token close = lexer_.next();
  std::erase_if(digits.text, [](char c) { return c == ' ' || c == '\t'; });
  // DPRNT takes [c d] (two digits), BPRNT only [d] (spec §7.3, §7.4).
  std::size_t want = statement == "BPRNT" ? 1 : 2;
  if (digits.kind != Tok::Number || digits.hasDecimal ||
      digits.text.size() != want || close.kind != Tok::RBracket) {
    diags_.report(want == 2 ? DiagKind::PrintBadFormat
                            : DiagKind::BprntBadFormat,
                  open.range);
    fail();
  }
  item.intDigits = want == 2 ? digits.text[0] - '0' : 0;
  item.fracDigits = digits.text.back() - '0';
  item.range = {hash.range.begin,
                close.range.begin.offset + 1 - hash.range.begin.offset};
  ahead_.clear();
  tok_ = lexer_.nextPrint();
  return item;
}

} // namespace mbc::detail
