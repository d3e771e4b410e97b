// The Macro B lexer (see lexer.h for the rules it follows).
#include "frontend/lexer.h"

#include "frontend/utf8.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

namespace mbc {

namespace {

struct WordRow {
  std::string_view spelling;
  bool isFunction;
  Keyword keyword;
  Builtin builtin;
};

constexpr WordRow kw(std::string_view s, Keyword k) {
  return {s, false, k, Builtin::Sin};
}

constexpr WordRow fn(std::string_view s, Builtin b) {
  return {s, true, Keyword::If, b};
}

constexpr std::array kWords = {
    kw("IF", Keyword::If),       kw("GOTO", Keyword::Goto),
    kw("THEN", Keyword::Then),   kw("WHILE", Keyword::While),
    kw("DO", Keyword::Do),       kw("END", Keyword::End),
    kw("EQ", Keyword::Eq),       kw("NE", Keyword::Ne),
    kw("GT", Keyword::Gt),       kw("GE", Keyword::Ge),
    kw("LT", Keyword::Lt),       kw("LE", Keyword::Le),
    kw("AND", Keyword::And),     kw("OR", Keyword::Or),
    kw("XOR", Keyword::Xor),     kw("MOD", Keyword::Mod),
    kw("DPRNT", Keyword::Dprnt), kw("BPRNT", Keyword::Bprnt),
    kw("POPEN", Keyword::Popen), kw("PCLOS", Keyword::Pclos),
// The functions, from builtins.def. ATAN finds its first row, the
// one-argument builtin; the parser turns the two-argument forms into Atan2.
#define BUILTIN(Id, Name, Arity) fn(Name, Builtin::Id),
#include <mbc/builtins.def>
};

// The two-letter abbreviations of macro words that FANUC controls read
// (docs/language.md): two letters in a row have no other meaning, since an
// address is always followed by its value. PO is POW before '[' and
// POPEN otherwise.
constexpr std::array<std::pair<std::string_view, std::string_view>, 26>
    kAbbreviations = {{
        {"AB", "ABS"},   {"AC", "ACOS"},  {"AD", "ADP"},   {"AN", "AND"},
        {"AS", "ASIN"},  {"AT", "ATAN"},  {"BC", "BCD"},   {"BI", "BIN"},
        {"BP", "BPRNT"}, {"CO", "COS"},   {"DP", "DPRNT"}, {"EN", "END"},
        {"EX", "EXP"},   {"FI", "FIX"},   {"FU", "FUP"},   {"GO", "GOTO"},
        {"MO", "MOD"},   {"PC", "PCLOS"}, {"PO", "POPEN"}, {"RO", "ROUND"},
        {"SI", "SIN"},   {"SQ", "SQRT"},  {"TA", "TAN"},   {"TH", "THEN"},
        {"WH", "WHILE"}, {"XO", "XOR"},
    }};

// The word a two-letter abbreviation stands for, or nullptr.
const WordRow* abbreviated(std::string_view letters, bool bracketFollows) {
  for (const auto& [abbreviation, word] : kAbbreviations) {
    if (letters != abbreviation) {
      continue;
    }
    const std::string_view spelling =
        word == "POPEN" && bracketFollows ? "POW" : word;
    for (const WordRow& w : kWords) {
      if (w.spelling == spelling) {
        return &w;
      }
    }
  }
  return nullptr;
}

bool isLetter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

} // namespace

std::string describe(const Token& t) {
  switch (t.kind) {
    case Tok::EndOfBlock:
      return "the end of the block";
    case Tok::EndOfFile:
      return "the end of the file";
    case Tok::Percent:
      return "'%'";
    case Tok::Number:
      if (t.text.find_first_of("0123456789") == std::string::npos) {
        return t.text == "." ? "a decimal point without digits"
                             : "'" + t.text + "'";
      }
      return "number '" + t.text + "'";
    case Tok::Letter:
      return "address " + t.text;
    case Tok::ProgramName:
      return "program name";
    case Tok::Comment:
      return "comment";
    case Tok::Keyword:
    case Tok::Function:
      return "'" + t.text + "'";
    case Tok::PrintText:
      return "text";
    case Tok::Invalid:
      return "invalid character";
    default:
      return "'" + t.text + "'";
  }
}

Lexer::Lexer(const SourceManager& sources, std::uint32_t file,
             DiagnosticEngine& diags)
    : sources_(sources), file_(file), diags_(diags), text_(sources.text(file)) {
  findTextBounds();
}

// The first '%' from `from` that is program text: a '%' inside a ( )
// comment or after ';' on its line is comment text ("(50% STEPOVER)").
std::size_t Lexer::findClosingPercent(std::uint32_t from) const {
  bool inParen = false, inLineComment = false;
  for (std::size_t i = from; i < text_.size(); ++i) {
    char c = text_[i];
    if (c == '\n' || isLoneCr(static_cast<std::uint32_t>(i))) {
      inParen = inLineComment = false;
    } else if (inLineComment) {
      continue;
    } else if (c == '(') {
      inParen = true;
    } else if (c == ')') {
      inParen = false;
    } else if (c == ';' && !inParen) {
      inLineComment = true;
    } else if (c == '%' && !inParen) {
      return i;
    }
  }
  return std::string_view::npos;
}

// The program text lies between the two '%' marks; what comes before the
// first is leader (spec §1.1). A file with a single '%' (a listing that only
// ends with one) runs from its start to that '%'.
void Lexer::findTextBounds() {
  auto size = static_cast<std::uint32_t>(text_.size());
  pos_ = 0;
  std::size_t first = findClosingPercent(0);
  if (first != std::string_view::npos &&
      findClosingPercent(static_cast<std::uint32_t>(first) + 1) !=
          std::string_view::npos) {
    pos_ = static_cast<std::uint32_t>(first) + 1;
    while (pos_ < size && text_[pos_] != '\n' && !isLoneCr(pos_)) {
      ++pos_;
    }
  } else if (first != std::string_view::npos) {
    // A lone '%' that opens the file starts an unterminated text.
    std::uint32_t i = 0;
    while (i < size && (isBlank(text_[i]) || text_[i] == '\n')) {
      ++i;
    }
    if (i == first) {
      pos_ = i + 1;
    }
  }
  std::size_t close = findClosingPercent(pos_);
  end_ = close == std::string_view::npos ? size
                                         : static_cast<std::uint32_t>(close);
  if (close == std::string_view::npos) {
    return;
  }
  for (std::uint32_t j = end_ + 1; j < size; ++j) {
    char c = text_[j];
    if (!isBlank(c) && c != '\n' && c != '%') {
      diags_.report(DiagKind::TextAfterPercent, {{file_, end_}, 1});
      break;
    }
  }
}

char Lexer::upperAt(std::uint32_t i) {
  char c = text_[i];
  if (c >= 'a' && c <= 'z') {
    if (!warnedLowerCase_) {
      warnedLowerCase_ = true;
      diags_.report(DiagKind::LowerCase, {{file_, i}, 1});
    }
    return static_cast<char>(c - 'a' + 'A');
  }
  return c;
}

Token Lexer::make(Tok kind, std::uint32_t begin) {
  Token t;
  t.kind = kind;
  t.range = {{file_, begin}, pos_ - begin};
  t.text = std::string(text_.substr(begin, pos_ - begin));
  return t;
}

// CR is ignored before LF; a CR that ends a line on its own (old Mac files)
// ends the block like LF.
bool Lexer::isLoneCr(std::uint32_t i) const {
  return text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n');
}

void Lexer::skipSpaces() {
  while (pos_ < end_ && isBlank(text_[pos_]) && !isLoneCr(pos_)) {
    ++pos_;
  }
}

void Lexer::skipBlock() {
  while (pos_ < end_ && text_[pos_] != '\n' && !isLoneCr(pos_)) {
    ++pos_;
  }
}

Token Lexer::next() {
  skipSpaces();
  std::uint32_t begin = pos_;
  if (pos_ >= end_) {
    Token t;
    t.kind = Tok::EndOfFile;
    t.range = {{file_, end_}, 0};
    return t;
  }
  char c = text_[pos_];
  if (c == '\n' || isLoneCr(pos_)) {
    ++pos_;
    return make(Tok::EndOfBlock, begin);
  }
  if (c == ';') {
    ++pos_;
    Token t = make(Tok::EndOfBlock, begin);
    skipBlock();
    if (pos_ < end_) {
      ++pos_;
    }
    return t;
  }
  if (isDigit(c) || c == '.') {
    return lexNumber(begin);
  }
  if (isLetter(c)) {
    return lexWord(begin);
  }
  if (c == '(') {
    return lexComment(begin);
  }
  if (static_cast<unsigned char>(c) >= 0x80) {
    return lexNonAscii(begin);
  }
  return lexSpecial(begin);
}

Token Lexer::lexSpecial(std::uint32_t begin) {
  char c = text_[pos_++];
  switch (c) {
    case '#':
      return make(Tok::Hash, begin);
    case '[':
      return make(Tok::LBracket, begin);
    case ']':
      return make(Tok::RBracket, begin);
    case ',':
      return make(Tok::Comma, begin);
    case '+':
      return make(Tok::Plus, begin);
    case '-':
      return make(Tok::Minus, begin);
    case '*':
      return make(Tok::Star, begin);
    case '/':
      return make(Tok::Slash, begin);
    case '=':
      return make(Tok::Equal, begin);
    case ':': {
      // ISO code writes ':' for the program number address O.
      Token t = make(Tok::Letter, begin);
      t.text = "O";
      return t;
    }
    case '<': {
      while (pos_ < end_ && text_[pos_] != '>' && text_[pos_] != '\n') {
        ++pos_;
      }
      if (pos_ < end_ && text_[pos_] == '>') {
        ++pos_;
        Token t = make(Tok::ProgramName, begin);
        for (char& ch : t.text) {
          ch = (ch >= 'a' && ch <= 'z') ? static_cast<char>(ch - 32) : ch;
        }
        return t;
      }
      pos_ = begin + 1;
      break;
    }
    case '_':
      // #_ABSMT[1]: a 30i-B system variable by name.
      if (begin > 0 && text_[begin - 1] == '#') {
        std::uint32_t end = begin + 1;
        while (end < end_ &&
               (std::isalnum(static_cast<unsigned char>(text_[end])) != 0 ||
                text_[end] == '_')) {
          ++end;
        }
        pos_ = end;
        Token t = make(Tok::Invalid, begin);
        diags_.report(DiagKind::VariableNameUnsupported, t.range,
                      std::string(text_.substr(begin + 1, end - begin - 1)));
        return t;
      }
      break;
    default:
      break;
  }
  Token t = make(Tok::Invalid, begin);
  diags_.report(DiagKind::InvalidCharacter, t.range, shownCharacter(t.text));
  return t;
}

// UTF-8 dashes come from word processors; they get a fix-it and are read as
// '-' so that the rest of the block is still checked.
Token Lexer::lexNonAscii(std::uint32_t begin) {
  static constexpr std::array<std::string_view, 4> kDashes = {
      "\xE2\x80\x93", "\xE2\x80\x94", "\xE2\x88\x92", "\xE2\x80\x92"};
  for (std::string_view d : kDashes) {
    if (text_.substr(begin, d.size()) == d) {
      pos_ = begin + static_cast<std::uint32_t>(d.size());
      Token t = make(Tok::Minus, begin);
      diags_.report(DiagKind::UnicodeDash, t.range, std::string(d))
          .fixIts.push_back({t.range, "-"});
      return t;
    }
  }
  ++pos_;
  while (pos_ < end_ &&
         (static_cast<unsigned char>(text_[pos_]) & 0xC0) == 0x80) {
    ++pos_;
  }
  Token t = make(Tok::Invalid, begin);
  diags_.report(DiagKind::InvalidCharacter, t.range, shownCharacter(t.text));
  return t;
}

Token Lexer::lexNumber(std::uint32_t begin) {
  std::string digits;
  bool dot = false;
  std::uint32_t last = pos_;
  while (pos_ < end_) {
    char c = text_[pos_];
    if (isDigit(c) || (c == '.' && !dot)) {
      dot = dot || c == '.';
      digits += c;
      last = ++pos_;
      continue;
    }
    // Spaces are ignored inside a number too ("X1 00." is X100.).
    std::uint32_t look = pos_;
    while (look < end_ && (text_[look] == ' ' || text_[look] == '\t')) {
      ++look;
    }
    if (look > pos_ && look < end_ &&
        (isDigit(text_[look]) || (text_[look] == '.' && !dot))) {
      pos_ = look;
      continue;
    }
    break;
  }
  pos_ = last;
  // "0.012." would read as 0.012 and a number 0: say what is wrong instead,
  // and take it into the number so that one mistake makes one error. A
  // letter after a number is the next word ("F800E41" is F800 and E41).
  if (dot && pos_ < end_ && text_[pos_] == '.') {
    const std::uint32_t second = pos_;
    skipNumberRest();
    if (digits != ".") { // "..." is an ellipsis, not a number
      diags_.report(DiagKind::SecondDecimalPoint, {{file_, second}, 1});
    }
  }
  Token t = make(Tok::Number, begin);
  t.hasDecimal = dot;
  if (digits == ".") {
    digits = "0";
  }
  double v = 0;
  auto res = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (res.ec == std::errc::result_out_of_range || !std::isfinite(v) ||
      v > 1e300) {
    diags_.report(DiagKind::NumberTooLarge, t.range);
    v = 0;
  }
  t.number = v;
  return t;
}

void Lexer::skipNumberRest() {
  while (pos_ < end_ && (isDigit(text_[pos_]) || text_[pos_] == '.')) {
    ++pos_;
  }
}

Token Lexer::lexWord(std::uint32_t begin) {
  std::string run;
  for (std::uint32_t i = pos_; i < end_ && run.size() < 6 && isLetter(text_[i]);
       ++i) {
    run += upperAt(i);
  }
  const WordRow* best = nullptr;
  for (const WordRow& w : kWords) {
    if (run.starts_with(w.spelling) &&
        (!best || w.spelling.size() > best->spelling.size())) {
      best = &w;
    }
  }
  std::uint32_t length =
      best ? static_cast<std::uint32_t>(best->spelling.size()) : 0;
  // Two letters and a third are stray text (ASSY), not an abbreviation.
  if (!best && run.size() == 2) {
    std::uint32_t next = pos_ + 2;
    while (next < end_ && isBlank(text_[next])) {
      ++next;
    }
    best = abbreviated(run.substr(0, 2), next < end_ && text_[next] == '[');
    length = 2;
  }
  if (!best) {
    ++pos_;
    Token t = make(Tok::Letter, begin);
    t.text = std::string(1, run[0]);
    return t;
  }
  pos_ += length;
  Token t = make(best->isFunction ? Tok::Function : Tok::Keyword, begin);
  t.text = std::string(best->spelling);
  t.keyword = best->keyword;
  t.builtin = best->builtin;
  return t;
}

Token Lexer::lexComment(std::uint32_t begin) {
  ++pos_;
  while (pos_ < end_ && text_[pos_] != ')' && text_[pos_] != '\n') {
    ++pos_;
  }
  if (pos_ < end_ && text_[pos_] == ')') {
    ++pos_;
    Token t = make(Tok::Comment, begin);
    t.text = t.text.substr(1, t.text.size() - 2);
    return t;
  }
  std::uint32_t stop = pos_;
  while (stop > begin && isBlank(text_[stop - 1])) {
    --stop;
  }
  Token t = make(Tok::Comment, begin);
  t.text = std::string(text_.substr(begin + 1, stop - begin - 1));
  diags_.report(DiagKind::UnterminatedComment, {{file_, begin}, 1})
      .fixIts.push_back({{{file_, stop}, 0}, ")"});
  return t;
}

Token Lexer::nextPrint() {
  skipSpaces();
  std::uint32_t begin = pos_;
  std::string text;
  while (pos_ < end_) {
    char c = text_[pos_];
    if (c == '#' || c == '[' || c == ']' || c == '\n' || c == ';' || c == '(' ||
        static_cast<unsigned char>(c) >= 0x80 ||
        static_cast<unsigned char>(c) < 0x20) {
      if (isBlank(c)) {
        ++pos_;
        continue;
      }
      break;
    }
    // Spaces are not printed: the control ignores them; '*' prints a space.
    if (c != ' ') {
      text += upperAt(pos_);
    }
    ++pos_;
  }
  if (text.empty()) {
    pos_ = begin;
    return next();
  }
  Token t = make(Tok::PrintText, begin);
  t.text = text;
  return t;
}

} // namespace mbc
