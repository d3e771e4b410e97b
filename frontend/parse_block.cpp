// Programs and blocks: '%', O numbers and <NAME> headers, '/' block skip, N
// sequence numbers, and the end-of-block resynchronisation after an error.
#include "frontend/parser.h"
#include <mbc/addresses.h>

#include <cctype>
#include <cmath>
#include <optional>

namespace mbc {

void parseFile(const SourceManager& sources, std::uint32_t file,
               DiagnosticEngine& diags, const ParseOptions& options,
               Unit& unit) {
  detail::Parser(sources, file, diags, options, unit).run();
}

namespace detail {

Parser::Parser(const SourceManager& sources, std::uint32_t file,
               DiagnosticEngine& diags, const ParseOptions& options, Unit& unit)
    : sources_(sources), file_(file), diags_(diags), options_(options),
      unit_(unit), lexer_(sources, file, diags), inch_(options.inch) {
}

void Parser::advance() {
  previous_ = std::move(tok_);
  for (;;) {
    if (!ahead_.empty()) {
      tok_ = std::move(ahead_.front());
      ahead_.pop_front();
    } else {
      tok_ = lexer_.next();
    }
    if (tok_.kind != Tok::Comment) {
      return;
    }
    blockComments_.push_back(tok_);
  }
}

const Token& Parser::peek() {
  while (ahead_.empty() || ahead_.back().kind == Tok::Comment) {
    Token t = lexer_.next();
    if (t.kind == Tok::Comment) {
      blockComments_.push_back(t);
      continue;
    }
    ahead_.push_back(std::move(t));
  }
  return ahead_.back();
}

void Parser::fail() {
  throw BlockError{};
}

// The lexer already reported an invalid character; saying "unexpected" about
// it again would only repeat the same error.
void Parser::unexpected(DiagKind kind) {
  if (tok_.kind != Tok::Invalid) {
    diags_.report(kind, tok_.range, describe(tok_));
  }
  fail();
}

void Parser::run() {
  advance();
  while (tok_.kind != Tok::EndOfFile &&
         !(options_.stopAtErrorLimit && diags_.tooManyErrors())) {
    parseBlock();
  }
}

Program& Parser::currentProgram(SourceLoc at) {
  if (program_ < 0) {
    // Blocks before any O number form the anonymous main program.
    Program p;
    p.name = "MAIN";
    p.range = {at, 0};
    p.file = file_;
    for (const Program& other : unit_.programs) {
      if (other.name == p.name && !other.duplicate) {
        diags_.report(DiagKind::DuplicateProgram, p.range, p.name);
        p.duplicate = true;
      }
    }
    unit_.programs.push_back(std::move(p));
    program_ = static_cast<int>(unit_.programs.size() - 1);
  }
  return unit_.programs[program_];
}

// program-header := ('O' number | '<' NAME '>') comment* EOB
bool Parser::parseProgramHeader() {
  Token start = tok_;
  Program p;
  p.file = file_;
  if (tok_.kind == Tok::ProgramName) {
    if (tok_.text == "<>") {
      diags_.report(DiagKind::EmptyProgramName, tok_.range);
    }
    p.name = tok_.text;
    advance();
  } else {
    advance();
    if (tok_.kind == Tok::Hash) {
      diags_.report(DiagKind::VariableNotAllowedHere, tok_.range, "O");
      fail();
    }
    if (tok_.kind != Tok::Number || tok_.hasDecimal) {
      diags_.report(DiagKind::ExpectedProgramNumber, start.range,
                    kMaxProgramNumber);
      fail();
    }
    if (tok_.number < 1 || tok_.number > kMaxProgramNumber) {
      diags_.report(DiagKind::ProgramNumberRange, tok_.range, tok_.text,
                    kMaxProgramNumber);
      fail();
    }
    p.number = static_cast<int>(tok_.number);
    p.name = programName(p.number);
    advance();
  }
  p.range = {start.range.begin,
             tok_.range.begin.offset - start.range.begin.offset};
  for (const Program& other : unit_.programs) {
    if (other.name == p.name && !other.duplicate) {
      diags_.report(DiagKind::DuplicateProgram, start.range, p.name);
      diags_.note(DiagKind::ProgramDefinedHere, other.range, p.name);
      p.duplicate = true;
    }
  }
  unit_.programs.push_back(std::move(p));
  program_ = static_cast<int>(unit_.programs.size() - 1);
  if (tok_.kind != Tok::EndOfBlock && tok_.kind != Tok::EndOfFile) {
    unexpected(DiagKind::ExpectedEndOfBlock);
  }
  return true;
}

// block := ['/' [digit]] ['N' number] statement comment* EOB
void Parser::parseBlock() {
  blockComments_.clear();
  reportedDepth_ = false;
  operands_ = 0;
  Block b;
  b.range.begin = tok_.range.begin;
  b.line = sources_.lineCol(tok_.range.begin).line;
  SourceRange seqRange;
  macroStatement_ = false;
  try {
    if ((tok_.kind == Tok::Letter && tok_.text == "O") ||
        tok_.kind == Tok::ProgramName) {
      parseProgramHeader();
      // An error on the header line (a comment not closed) is the new
      // program's first block.
      b.range.length = tok_.range.begin.offset - b.range.begin.offset;
      pushBlock(b);
      advance();
      return;
    }
    for (int pass = 0; pass < 2; ++pass) {
      if (tok_.kind == Tok::Slash && b.skipLevel == 0) {
        advance();
        b.skipLevel = 1;
        if (tok_.kind == Tok::Number && !tok_.hasDecimal && tok_.number >= 1 &&
            tok_.number <= 9) {
          b.skipLevel = static_cast<int>(tok_.number);
          advance();
        }
      }
      if (tok_.kind == Tok::Letter && tok_.text == "N" && b.seq < 0) {
        Token n = tok_;
        advance();
        if (tok_.kind == Tok::Hash) {
          diags_.report(DiagKind::VariableNotAllowedHere, tok_.range, "N");
          fail();
        }
        if (tok_.kind != Tok::Number || tok_.hasDecimal || tok_.number < 1 ||
            tok_.number > kMaxSequenceNumber) {
          diags_.report(DiagKind::ExpectedSequenceNumber, n.range,
                        kMaxSequenceNumber);
          fail();
        }
        b.seq = static_cast<int>(tok_.number);
        seqRange = {n.range.begin, tok_.range.begin.offset + tok_.range.length -
                                       n.range.begin.offset};
        advance();
      }
    }
    parseStatement(b);
    expectEndOfBlock(b.stmt);
    addSequenceWord(b, seqRange);
  } catch (const BlockError&) {
    takeAlarm(b);
    resynchronise();
    keepBrokenBlock(b);
    return;
  }
  b.range.length = tok_.range.begin.offset - b.range.begin.offset;
  takeAlarm(b); // before the split: a block with an error alarms whole
  splitLeadCodes(b, seqRange);
  pushBlock(b);
  advance();
}

// The first error of the block becomes the alarm it raises when it runs.
// Called before the lexer moves on to the next block, whose errors are its
// own.
void Parser::takeAlarm(Block& b) {
  const DiagnosticEngine::BlockError error = diags_.takeBlockError();
  if (!error.kind || b.alarm != AlarmId::None) {
    return;
  }
  b.alarm = runTimeAlarm(*error.kind);
  // An unreadable part of a macro statement is a macro format error.
  if (macroStatement_ && b.alarm == AlarmId::ImproperNcAddress) {
    b.alarm = AlarmId::MacroStatementFormat;
    diags_.setAlarm(error, b.alarm);
  }
  b.alarmDetail = alarmDetail(error.message);
}

void Parser::pushBlock(Block& b) {
  takeAlarm(b);
  if (b.stmt.kind != StmtKind::Empty || b.seq >= 0 ||
      b.alarm != AlarmId::None) {
    currentProgram(b.range.begin).blocks.push_back(std::move(b));
  }
}

// G codes written before G65 (G57 G65 P..., as some shops begin every
// call) take effect before the call: they become an NC block of their own
// on the same line, which takes the N number as GOTO's target.
void Parser::splitLeadCodes(Block& b, SourceRange seqRange) {
  if (b.stmt.kind != StmtKind::MacroCall || b.stmt.leadCodes.empty()) {
    return;
  }
  Block codes;
  codes.range = b.range;
  codes.line = b.line;
  codes.seq = b.seq;
  codes.skipLevel = b.skipLevel;
  codes.stmt.kind = StmtKind::Nc;
  codes.stmt.range = b.stmt.range;
  codes.stmt.words = std::move(b.stmt.leadCodes);
  b.stmt.leadCodes.clear();
  addSequenceWord(codes, seqRange);
  b.seq = -1;
  codes.alarm = b.alarm;
  codes.alarmDetail = b.alarmDetail;
  currentProgram(b.range.begin).blocks.push_back(std::move(codes));
}

// #4114 holds the N of the last NC block (spec §6.4): the runtime gets it as
// the block's first word. A block of just an N number is an NC block too.
void Parser::addSequenceWord(Block& b, SourceRange range) {
  if (b.seq < 0 ||
      (b.stmt.kind != StmtKind::Nc && b.stmt.kind != StmtKind::Empty)) {
    return;
  }
  if (b.stmt.kind == StmtKind::Empty) {
    b.stmt.kind = StmtKind::Nc;
    b.stmt.range = range;
  }
  Word w;
  w.letter = 'N';
  w.kind = WordKind::IntLiteral;
  w.range = range;
  w.value = std::make_unique<Expr>();
  w.value->range = range;
  w.value->number = b.seq;
  b.stmt.words.insert(b.stmt.words.begin(), std::move(w));
}

std::string Parser::sourceText(SourceRange r) const {
  return std::string(
      sources_.text(r.begin.file).substr(r.begin.offset, r.length));
}

// Functions and statements of the 30i-B that mbc does not have: the block
// stops with MBC0001 naming them, where the letters would otherwise read as
// addresses (docs/control-tables.md).
void Parser::refuseUnsupportedFunction(const Token& letter) {
  struct Form {
    std::string_view name;
    const char* what;
    bool bracket; // written NAME[...]
  };

  static constexpr Form kForms[] = {
      {"AXNUM", "the number of an axis address", true},
      {"AX", "an axis address by its number", true},
      {"SETVN", "names for common variables", false},
  };
  const std::string_view text = sources_.text(letter.range.begin.file);
  const std::size_t begin = letter.range.begin.offset;
  std::size_t end = begin;
  while (end < text.size() &&
         std::isalpha(static_cast<unsigned char>(text[end])) != 0) {
    ++end;
  }
  std::string word(text.substr(begin, end - begin));
  for (char& ch : word) {
    ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  }
  for (const Form& form : kForms) {
    if (word == form.name &&
        (!form.bracket || (end < text.size() && text[end] == '['))) {
      SourceRange range = letter.range;
      range.length = static_cast<std::uint32_t>(end - begin);
      diags_.report(DiagKind::UnsupportedFunction, range, form.name, form.what);
      fail();
    }
  }
}

std::optional<SourceRange> Parser::strayText(const Token& letter) const {
  const std::string_view text = sources_.text(letter.range.begin.file);
  const std::size_t begin = letter.range.begin.offset;
  const auto isLetter = [&](std::size_t i) {
    return i < text.size() &&
           std::isalpha(static_cast<unsigned char>(text[i])) != 0;
  };
  // An address is followed by its value, so three letters in a row are
  // words; two may be an address missing its value next to another one.
  if (!isLetter(begin + 1) || !isLetter(begin + 2)) {
    return std::nullopt;
  }
  std::size_t end = text.find('\n', begin);
  end = end == std::string_view::npos ? text.size() : end;
  const std::string_view rest = text.substr(begin, end - begin);
  std::size_t length = rest.find_first_of("();");
  if (length == std::string_view::npos) {
    length = rest.find_last_not_of(" \t\r") + 1; // the rest of the line
  } else {
    length = 0; // up to a comment or a statement: the word alone
    while (isLetter(begin + length)) {
      ++length;
    }
  }
  SourceRange range = letter.range;
  range.length = static_cast<std::uint32_t>(length);
  return range;
}

// `COS(#1)` or `X(#1+5.)`: the '(' was read as a comment, which is the real
// mistake; say so.
void Parser::noteParenthesis(const Token& after) {
  if (blockComments_.empty()) {
    return;
  }
  const Token& c = blockComments_.back();
  std::uint32_t end = after.range.begin.offset + after.range.length;
  if (c.range.begin.offset >= end &&
      c.range.begin.offset <= tok_.range.begin.offset) {
    diags_.note(DiagKind::ParenthesisIsComment, c.range);
  }
}

namespace {

// The loop number after "DO" or "END" at `at` (spaces between), or 0.
int loopNumberAt(std::string_view text, std::size_t at) {
  while (at < text.size() && text[at] == ' ') {
    ++at;
  }
  return at < text.size() && text[at] >= '1' && text[at] <= '9' ? text[at] - '0'
                                                                : 0;
}

} // namespace

// A block with an error raises its alarm when it runs, but its N number and
// the DOm/ENDm of a WHILE, DO or END statement still matter: without them one
// typo would also be reported as a missing GOTO target or an unmatched loop,
// and the loop around it would not be one.
void Parser::keepBrokenBlock(Block& b) {
  bool loop =
      (b.stmt.kind == StmtKind::While || b.stmt.kind == StmtKind::End) &&
      b.stmt.loopId > 0;
  if (!loop) {
    const SourceLoc from = b.stmt.range.begin.offset > b.range.begin.offset
                               ? b.stmt.range.begin
                               : b.range.begin;
    b.stmt = Stmt{};
    b.stmt.range.begin = from;
    // The statement as the lexer reads it: upper case, without comments.
    const std::string_view line = sources_.lineText(from);
    const std::size_t column = sources_.lineCol(from).col - 1;
    std::string text;
    int depth = 0;
    for (char c : line.substr(std::min(column, line.size()))) {
      depth += c == '(' ? 1 : c == ')' && depth > 0 ? -1 : 0;
      if (c == ';') {
        break;
      }
      if (depth == 0 && c != ')') {
        text += c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c;
      }
    }
    const std::size_t first = text.find_first_not_of(' ');
    std::string_view statement =
        first == std::string::npos ? "" : std::string_view(text).substr(first);
    if (statement.starts_with("WH")) {
      const std::size_t d = statement.rfind("DO");
      b.stmt.loopId =
          d == std::string_view::npos ? 0 : loopNumberAt(statement, d + 2);
      b.stmt.kind = StmtKind::While;
    } else if (statement.starts_with("DO")) {
      b.stmt.loopId = loopNumberAt(statement, 2);
      b.stmt.kind = StmtKind::While;
    } else if (statement.starts_with("EN")) {
      b.stmt.loopId =
          loopNumberAt(statement, statement.starts_with("END") ? 3 : 2);
      b.stmt.kind = StmtKind::End;
    } else {
      // Stray characters before the keyword ("**END1", pasted markdown).
      for (std::size_t i = 0; i + 2 < statement.size(); ++i) {
        const bool end = statement.substr(i, 3) == "END";
        if (end || statement.substr(i, 2) == "DO") {
          b.stmt.loopId = loopNumberAt(statement, i + (end ? 3 : 2));
          b.stmt.kind = end ? StmtKind::End : StmtKind::While;
          if (b.stmt.loopId != 0) {
            break;
          }
        }
      }
    }
    if (b.stmt.loopId == 0) {
      b.stmt.kind = StmtKind::Empty;
    }
  }
  b.range.length = tok_.range.begin.offset - b.range.begin.offset;
  currentProgram(b.range.begin).blocks.push_back(std::move(b));
}

// After an error: continue with the first token of the next block, wherever
// the lexer stands (the end of the block may already be in tok_ or ahead_).
void Parser::resynchronise() {
  while (tok_.kind != Tok::EndOfBlock && tok_.kind != Tok::EndOfFile) {
    if (ahead_.empty()) {
      lexer_.skipBlock();
    }
    advance();
  }
  if (tok_.kind == Tok::EndOfBlock) {
    advance();
  }
}

// "1.5E3" where an expression goes on: in an NC block a letter after a
// number is the next word (F800E41), but inside a macro statement or brackets
// it can only be a mistaken exponent.
void Parser::rejectExponent() {
  const SourceRange& number = previous_.range;
  if (previous_.kind != Tok::Number || tok_.kind != Tok::Letter ||
      tok_.text != "E" ||
      number.begin.offset + number.length != tok_.range.begin.offset) {
    return;
  }
  std::string_view text = sources_.text(file_);
  std::uint32_t end = tok_.range.begin.offset + 1;
  if (end < text.size() && (text[end] == '-' || text[end] == '+')) {
    ++end;
  }
  if (end >= text.size() || text[end] < '0' || text[end] > '9') {
    return;
  }
  while (end < text.size() && text[end] >= '0' && text[end] <= '9') {
    ++end;
  }
  diags_.report(DiagKind::ExponentNotation,
                {number.begin, end - number.begin.offset});
  fail();
}

void Parser::expectEndOfBlock(const Stmt& s) {
  if (tok_.kind == Tok::EndOfBlock || tok_.kind == Tok::EndOfFile) {
    return;
  }
  if (s.kind != StmtKind::Nc && s.kind != StmtKind::MacroCall) {
    rejectExponent();
  }
  // A comma takes C, R or A only (parseWords reads those).
  if (s.kind == StmtKind::Nc && tok_.kind == Tok::Comma &&
      peek().kind == Tok::Letter) {
    const Token comma = tok_;
    const Token& letter = peek();
    diags_.report(DiagKind::CommaLetter,
                  {comma.range.begin, letter.range.begin.offset +
                                          letter.range.length -
                                          comma.range.begin.offset},
                  letter.text);
    fail();
  }
  bool macroNext =
      tok_.kind == Tok::Hash ||
      (tok_.kind == Tok::Keyword &&
       (tok_.keyword == Keyword::If || tok_.keyword == Keyword::While ||
        tok_.keyword == Keyword::Goto || tok_.keyword == Keyword::Dprnt ||
        tok_.keyword == Keyword::Bprnt || tok_.keyword == Keyword::Popen ||
        tok_.keyword == Keyword::Pclos));
  bool ncNext = tok_.kind == Tok::Letter;
  bool isNc = s.kind == StmtKind::Nc || s.kind == StmtKind::MacroCall;
  if ((isNc && macroNext) || (!isNc && s.kind != StmtKind::Empty && ncNext)) {
    diags_.report(DiagKind::MixedNcAndMacro, tok_.range);
    fail();
  }
  unexpected(DiagKind::ExpectedEndOfBlock);
}

const Token* Parser::messageAfter(std::uint32_t offset) const {
  for (const Token& c : blockComments_) {
    if (c.range.begin.offset > offset) {
      return &c;
    }
  }
  return nullptr;
}

} // namespace detail
} // namespace mbc
