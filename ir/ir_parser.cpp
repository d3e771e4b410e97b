// The IR text parser: the character cursor, functions and blocks. One
// instruction is parsed in ir_parse_inst.cpp. Errors are thrown as
// ParseError and turned into "line:col: message" by parseModule.
#include "ir/ir_parser.h"

#include "ir/ir_parse_internal.h"
#include <mbc/addresses.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <set>
#include <vector>

namespace mbc::ir {

namespace parse {

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

bool isWordChar(char c) {
  return isDigit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
         c == '_' || c == '.';
}

// The characters fmt may print for a double: digits, sign, point, exponent,
// "inf" and "nan".
bool isNumberChar(char c) {
  return isWordChar(c) || c == '+' || c == '-';
}

} // namespace

void Cursor::advance() {
  if (current() == '\n') {
    ++pos_.line;
    pos_.col = 1;
  } else {
    ++pos_.col;
  }
  ++i_;
}

void Cursor::skipBlanks() {
  while (current() == ' ' || current() == '\t' || current() == '\r') {
    advance();
  }
  if (current() == ';') {
    while (i_ < text_.size() && current() != '\n') {
      advance();
    }
  }
}

void Cursor::skipLines() {
  for (skipBlanks(); current() == '\n'; skipBlanks()) {
    advance();
  }
}

bool Cursor::atEnd() {
  skipBlanks();
  return i_ >= text_.size();
}

bool Cursor::atEol() {
  return atEnd() || current() == '\n';
}

void Cursor::endLine() {
  if (!atEol()) {
    fail(fmt::format("unexpected '{}' at the end of the line", current()));
  }
  if (i_ < text_.size()) {
    advance();
  }
}

bool Cursor::accept(char c) {
  skipBlanks();
  if (i_ < text_.size() && current() == c) {
    advance();
    return true;
  }
  return false;
}

void Cursor::expect(char c) {
  if (!accept(c)) {
    fail(fmt::format("expected '{}'", c));
  }
}

char Cursor::peek() {
  skipBlanks();
  return current();
}

bool Cursor::atLabel() {
  skipBlanks();
  std::size_t j = i_;
  if (j >= text_.size() || text_[j] != 'b') {
    return false;
  }
  for (++j; j < text_.size() && isDigit(text_[j]); ++j) {
  }
  return j > i_ + 1 && j < text_.size() && text_[j] == ':';
}

std::string_view Cursor::word(const char* what) {
  skipBlanks();
  std::size_t start = i_;
  while (i_ < text_.size() && isWordChar(current())) {
    advance();
  }
  if (start == i_) {
    fail(fmt::format("expected {}", what));
  }
  return text_.substr(start, i_ - start);
}

std::string_view Cursor::delimited(char open, char close) {
  expect(open);
  std::size_t start = i_;
  while (i_ < text_.size() && current() != close && current() != '\n') {
    advance();
  }
  std::string_view inside = text_.substr(start, i_ - start);
  expect(close);
  return inside;
}

std::int64_t Cursor::integer(const char* what) {
  skipBlanks();
  TextPos start = pos_;
  std::size_t from = i_;
  if (current() == '-') {
    advance();
  }
  while (isDigit(current())) {
    advance();
  }
  std::int64_t v = 0;
  auto [end, ec] = std::from_chars(text_.data() + from, text_.data() + i_, v);
  if (ec != std::errc() || end != text_.data() + i_) {
    failAt(start, fmt::format("expected {}", what));
  }
  return v;
}

std::int64_t Cursor::integer(const char* what, std::int64_t lo,
                             std::int64_t hi) {
  TextPos start = pos_;
  std::int64_t v = integer(what);
  if (v < lo || v > hi) {
    failAt(start, fmt::format("{} out of range", what));
  }
  return v;
}

double Cursor::number() {
  skipBlanks();
  TextPos start = pos_;
  std::size_t from = i_;
  while (i_ < text_.size() && isNumberChar(current())) {
    advance();
  }
  double v = 0;
  auto [end, ec] = std::from_chars(text_.data() + from, text_.data() + i_, v);
  if (from == i_ || ec != std::errc() || end != text_.data() + i_) {
    failAt(start, "expected a number");
  }
  return v;
}

std::string Cursor::string() {
  if (peek() != '"') {
    fail("expected a string");
  }
  TextPos start = pos_;
  advance();
  std::string out;
  while (current() != '"') {
    if (i_ >= text_.size()) {
      failAt(start, "unterminated string");
    }
    if (current() == '\\') {
      advance();
      if (current() != '"' && current() != '\\') {
        fail("unknown escape in string (only \\\" and \\\\)");
      }
    }
    out += current();
    advance();
  }
  advance();
  return out;
}

// `%N` or `bN`: the prefix, then digits with nothing in between.
std::uint32_t Cursor::id(char prefix, const char* what) {
  skipBlanks();
  TextPos start = pos_;
  if (current() != prefix ||
      !isDigit(i_ + 1 < text_.size() ? text_[i_ + 1] : '\0')) {
    fail(fmt::format("expected {}", what));
  }
  advance();
  std::int64_t n = 0;
  while (isDigit(current())) {
    n = std::min<std::int64_t>(n * 10 + (current() - '0'), kMaxId + 1LL);
    advance();
  }
  if (n > kMaxId) {
    failAt(start, fmt::format("{} is too large (at most {})", what, kMaxId));
  }
  return static_cast<std::uint32_t>(n);
}

ValueId Cursor::value() {
  return id('%', "a value (%N)");
}

BlockId Cursor::block() {
  return id('b', "a block (bN)");
}

void Cursor::fail(const std::string& message) const {
  failAt(pos_, message);
}

void Cursor::failAt(TextPos pos, const std::string& message) {
  throw ParseError{pos, message};
}

namespace {

/// func = "func" "@" name ["#" integer] string "{" EOL {block} "}" EOL ;
/// name = word | "<" {char} ">" ;
/// block = "b" N ":" EOL {inst} ;
class FunctionParser {
public:
  FunctionParser(Cursor& c, Module& m) : c_(c), module_(m) {}

  Function run();

private:
  void header();
  void label();
  void instruction();
  void finish();

  Cursor& c_;
  Module& module_;
  Function f_;
  std::vector<ParsedInst> pending_;
  std::set<ValueId> defined_;
  std::int64_t currentLine_ = 0; // the last begin's line in the block
};

void FunctionParser::header() {
  c_.skipBlanks();
  TextPos at = c_.pos();
  if (c_.word("'func'") != "func") {
    Cursor::failAt(at, "expected 'func'");
  }
  c_.expect('@');
  if (c_.peek() == '<') {
    f_.name = "<" + std::string(c_.delimited('<', '>')) + ">";
  } else {
    f_.name = c_.word("a function name");
  }
  if (c_.accept('#')) {
    std::int64_t n = c_.integer("a program number");
    if (n < 0 || n > kMaxCallNumber) {
      c_.fail("program number out of range");
    }
    f_.number = static_cast<int>(n);
  }
  f_.file = c_.string();
  c_.expect('{');
  c_.endLine();
}

void FunctionParser::label() {
  TextPos at = c_.pos();
  BlockId b = c_.block();
  if (b != f_.blocks.size()) {
    Cursor::failAt(at, fmt::format("expected label b{}: blocks are numbered "
                                   "in order from b0",
                                   f_.blocks.size()));
  }
  c_.expect(':');
  c_.endLine();
  f_.blocks.emplace_back();
  currentLine_ = 0;
}

// Without `!LINE` an instruction has the line of the last begin before it
// in its block; a begin has its own line.
void FunctionParser::instruction() {
  if (f_.blocks.empty()) {
    c_.fail("instruction outside a block (expected label b0:)");
  }
  ParsedInst p = parseInst(c_, module_);
  Inst& inst = p.inst;
  if (!p.hasLine) {
    std::int64_t line =
        inst.op == Op::Begin ? inst.get<SourceLine>().line : currentLine_;
    inst.line = static_cast<std::uint32_t>(line);
  }
  if (inst.op == Op::Begin) {
    currentLine_ = inst.get<SourceLine>().line;
  }
  if (p.hasId && !defined_.insert(p.id).second) {
    Cursor::failAt(p.pos, fmt::format("value %{} is defined twice", p.id));
  }
  inst.block = static_cast<BlockId>(f_.blocks.size() - 1);
  pending_.push_back(std::move(p));
}

// Places the instructions: written ids as they are, the others after the
// largest id written anywhere, so that an undefined operand cannot
// accidentally name one of them.
void FunctionParser::finish() {
  std::int64_t largest = -1;
  for (const ParsedInst& p : pending_) {
    if (p.hasId) {
      largest = std::max<std::int64_t>(largest, p.id);
    }
    for (ValueId op : p.inst.ops) {
      largest = std::max<std::int64_t>(largest, op);
    }
  }
  f_.insts.resize(static_cast<std::size_t>(largest + 1));
  for (ParsedInst& p : pending_) {
    auto id = p.hasId ? p.id : static_cast<ValueId>(f_.insts.size());
    if (!p.hasId) {
      f_.insts.emplace_back();
    }
    f_.blocks[p.inst.block].insts.push_back(id);
    f_.insts[id] = std::move(p.inst);
  }
}

Function FunctionParser::run() {
  header();
  for (;;) {
    c_.skipLines();
    if (c_.atEnd()) {
      c_.fail(fmt::format("missing '}}' at the end of @{}", f_.name));
    }
    if (c_.accept('}')) {
      c_.endLine();
      break;
    }
    if (c_.atLabel()) {
      label();
    } else {
      instruction();
    }
  }
  finish();
  return std::move(f_);
}

} // namespace

} // namespace parse

/// module = {func} ;
bool parseModule(std::string_view text, Module& out, std::string& error) {
  parse::Cursor c(text);
  Module m;
  try {
    for (c.skipLines(); !c.atEnd(); c.skipLines()) {
      m.functions.push_back(parse::FunctionParser(c, m).run());
    }
  } catch (const parse::ParseError& e) {
    error = fmt::format("{}:{}: {}", e.pos.line, e.pos.col, e.message);
    return false;
  }
  out = std::move(m);
  return true;
}

} // namespace mbc::ir
