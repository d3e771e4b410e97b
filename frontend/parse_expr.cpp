// Expressions with FANUC precedence (spec §3.2): functions and brackets,
// then * / AND MOD, then + - OR XOR, then one comparison. AND/OR/XOR are
// bitwise on numbers and logical on conditions.
#include "frontend/parser.h"
#include <mbc/addresses.h>
#include <mbc/engine.h>
#include <mbc/limits.h>

#include <cctype>
#include <cmath>

namespace mbc::detail {

namespace {

// Enough for any real program; it keeps evaluation recursion bounded.
constexpr int kMaxOperands = 4096;
// Past the control's limit the parser keeps checking the block, but stops
// descending here so that 10 000 nested brackets cannot exhaust the stack.
constexpr int kHardBracketDepth = 64;

bool relOpOf(const Token& t, RelOp& op) {
  if (t.kind != Tok::Keyword) {
    return false;
  }
  switch (t.keyword) {
    case Keyword::Eq:
      op = RelOp::Eq;
      return true;
    case Keyword::Ne:
      op = RelOp::Ne;
      return true;
    case Keyword::Gt:
      op = RelOp::Gt;
      return true;
    case Keyword::Ge:
      op = RelOp::Ge;
      return true;
    case Keyword::Lt:
      op = RelOp::Lt;
      return true;
    case Keyword::Le:
      op = RelOp::Le;
      return true;
    default:
      return false;
  }
}

bool isSumOp(const Token& t) {
  return t.kind == Tok::Plus || t.kind == Tok::Minus ||
         (t.kind == Tok::Keyword &&
          (t.keyword == Keyword::Or || t.keyword == Keyword::Xor));
}

bool isTermOp(const Token& t) {
  return t.kind == Tok::Star || t.kind == Tok::Slash ||
         (t.kind == Tok::Keyword &&
          (t.keyword == Keyword::And || t.keyword == Keyword::Mod));
}

BinOp binOpOf(const Token& t) {
  switch (t.kind) {
    case Tok::Plus:
      return BinOp::Add;
    case Tok::Minus:
      return BinOp::Sub;
    case Tok::Star:
      return BinOp::Mul;
    case Tok::Slash:
      return BinOp::Div;
    default:
      break;
  }
  switch (t.keyword) {
    case Keyword::And:
      return BinOp::And;
    case Keyword::Or:
      return BinOp::Or;
    case Keyword::Xor:
      return BinOp::Xor;
    default:
      return BinOp::Mod;
  }
}

SourceRange spanOf(const Expr& a, const Expr& b) {
  std::uint32_t end = b.range.begin.offset + b.range.length;
  return {a.range.begin, end - a.range.begin.offset};
}

} // namespace

void Parser::requireNumber(const Expr& e) {
  if (e.isCondition()) {
    diags_.report(DiagKind::ConditionAsNumber, e.range);
    fail();
  }
}

ExprPtr Parser::makeBinary(const Token& op, ExprPtr lhs, ExprPtr rhs) {
  auto e = std::make_unique<Expr>();
  e->binOp = binOpOf(op);
  e->range = spanOf(*lhs, *rhs);
  bool logical =
      e->binOp == BinOp::And || e->binOp == BinOp::Or || e->binOp == BinOp::Xor;
  if (logical && lhs->isCondition() && rhs->isCondition()) {
    e->kind = ExprKind::Logical;
  } else if (logical && lhs->isCondition() != rhs->isCondition()) {
    diags_.report(DiagKind::MixedLogical, op.range, op.text, op.text);
    fail();
  } else {
    requireNumber(*lhs);
    requireNumber(*rhs);
    e->kind = ExprKind::Binary;
  }
  if (++operands_ > kMaxOperands) {
    diags_.report(DiagKind::ExpressionTooLong, op.range, kMaxOperands);
    fail();
  }
  e->args.push_back(std::move(lhs));
  e->args.push_back(std::move(rhs));
  return e;
}

// expr := sum [relop sum]
ExprPtr Parser::parseExpr(int depth) {
  ExprPtr lhs = parseSum(depth, true);
  RelOp op;
  if (tok_.kind == Tok::Equal && depth > 0) {
    // `IF [#1 = 5]`: say how to compare, and read on as EQ.
    diags_.report(DiagKind::EqualsAsComparison, tok_.range)
        .fixIts.push_back({tok_.range, "EQ"});
    op = RelOp::Eq;
  } else if (!relOpOf(tok_, op)) {
    return lhs;
  }
  advance();
  // A signed operand after a comparison is common (`#1 GT -1`) and harmless.
  ExprPtr rhs = parseSum(depth, true);
  requireNumber(*lhs);
  requireNumber(*rhs);
  RelOp again;
  if (relOpOf(tok_, again)) {
    diags_.report(DiagKind::ChainedComparison, tok_.range);
    fail();
  }
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Compare;
  e->relOp = op;
  e->range = spanOf(*lhs, *rhs);
  e->args.push_back(std::move(lhs));
  e->args.push_back(std::move(rhs));
  return e;
}

// sum := term {('+'|'-'|'OR'|'XOR') term}
ExprPtr Parser::parseSum(int depth, bool allowSign) {
  ExprPtr lhs = parseTerm(depth, allowSign);
  while (isSumOp(tok_)) {
    Token op = tok_;
    advance();
    ExprPtr rhs = parseTerm(depth, false);
    lhs = makeBinary(op, std::move(lhs), std::move(rhs));
  }
  return lhs;
}

// term := unary {('*'|'/'|'AND'|'MOD') unary}
ExprPtr Parser::parseTerm(int depth, bool allowSign) {
  ExprPtr lhs = parseUnary(depth, allowSign);
  while (isTermOp(tok_)) {
    Token op = tok_;
    advance();
    ExprPtr rhs = parseUnary(depth, false);
    lhs = makeBinary(op, std::move(lhs), std::move(rhs));
  }
  return lhs;
}

// unary := ['-'|'+'] primary   (a sign only at the start of an expression or
// a bracket: `10+-#1` is illegal, `10+[-#1]` is fine; spec §3.1)
ExprPtr Parser::parseUnary(int depth, bool allowSign) {
  if (tok_.kind != Tok::Minus && tok_.kind != Tok::Plus) {
    return parsePrimary(depth);
  }
  Token sign = tok_;
  advance();
  ExprPtr operand = parsePrimary(depth);
  requireNumber(*operand);
  if (!allowSign) {
    auto& d = diags_.report(DiagKind::ConsecutiveOperators, sign.range);
    std::uint32_t end = operand->range.begin.offset + operand->range.length;
    SourceRange span{sign.range.begin, end - sign.range.begin.offset};
    d.fixIts.push_back({span, fmt::format("[{}]", sourceText(span))});
  }
  if (sign.kind == Tok::Plus) {
    // A sign makes an expression of a reference: like [#1], +#1 reads
    // vacant as 0 (spec §2.3b: only a plain reference copies vacancy).
    operand->bracketed = true;
    return operand;
  }
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Neg;
  e->range = {sign.range.begin, operand->range.begin.offset +
                                    operand->range.length -
                                    sign.range.begin.offset};
  e->args.push_back(std::move(operand));
  return e;
}

void Parser::enterBracket(int depth, const Token& at) {
  if (depth + 1 > options_.maxBracketDepth && !reportedDepth_) {
    reportedDepth_ = true;
    diags_.report(DiagKind::BracketNesting, at.range, depth + 1,
                  options_.maxBracketDepth);
  }
  if (depth + 1 > kHardBracketDepth) {
    fail();
  }
}

void Parser::addressInExpression(const Token& t) {
  refuseUnsupportedFunction(t);
  diags_.report(DiagKind::AddressInExpression, t.range, t.text);
  if (int var = argumentLocal(t.text[0])) {
    diags_.note(DiagKind::ArgumentVariableNote, t.range, t.text, var);
  }
  fail();
}

// primary := number | variable | '[' expr ']' | function
ExprPtr Parser::parsePrimary(int depth) {
  switch (tok_.kind) {
    case Tok::Number: {
      auto e = std::make_unique<Expr>();
      e->kind = ExprKind::Number;
      e->range = tok_.range;
      e->number = tok_.number;
      e->hasDecimal = tok_.hasDecimal;
      advance();
      return e;
    }
    case Tok::Hash:
      return parseVariable(depth);
    case Tok::LBracket:
      return parseBracketed(depth);
    case Tok::Function:
      return parseCall(depth);
    case Tok::Letter:
      if (startsParameterRead(tok_)) {
        return parseParameterRead(depth);
      }
      addressInExpression(tok_);
    default:
      unexpected(DiagKind::ExpectedExpression);
  }
}

ExprPtr Parser::parseBracketed(int depth) {
  Token open = tok_;
  enterBracket(depth, open);
  advance();
  ExprPtr inner = parseExpr(depth + 1);
  if (tok_.kind != Tok::RBracket) {
    rejectExponent();
    auto& d = diags_.report(DiagKind::ExpectedCloseBracket, tok_.range);
    d.fixIts.push_back({{tok_.range.begin, 0}, "]"});
    diags_.note(DiagKind::BracketOpenedHere, open.range);
    fail();
  }
  inner->range = {open.range.begin,
                  tok_.range.begin.offset + 1 - open.range.begin.offset};
  inner->bracketed = true;
  advance();
  return inner;
}

// variable := '#' (number | '[' expr ']')
ExprPtr Parser::parseVariable(int depth) {
  Token hash = tok_;
  advance();
  auto e = std::make_unique<Expr>();
  if (tok_.kind == Tok::Number) {
    e->kind = ExprKind::Var;
    // A fractional number is rounded: #0.5 is #1 (spec §2.2).
    double n = std::round(tok_.number);
    e->var = n >= kBeyondAnyVariable ? static_cast<int>(kBeyondAnyVariable)
                                     : static_cast<int>(n);
    e->range = {hash.range.begin, tok_.range.begin.offset + tok_.range.length -
                                      hash.range.begin.offset};
    advance();
    return e;
  }
  if (tok_.kind == Tok::LBracket) {
    ExprPtr index = parseBracketed(depth);
    requireNumber(*index);
    e->kind = ExprKind::Indirect;
    e->range = {hash.range.begin, index->range.begin.offset +
                                      index->range.length -
                                      hash.range.begin.offset};
    e->args.push_back(std::move(index));
    return e;
  }
  if (tok_.kind == Tok::Hash) {
    auto& d = diags_.report(DiagKind::DoubleHash, hash.range);
    const Token& number = peek();
    if (number.kind == Tok::Number) {
      SourceRange inner{tok_.range.begin, number.range.begin.offset +
                                              number.range.length -
                                              tok_.range.begin.offset};
      d.fixIts.push_back({inner, fmt::format("[{}]", sourceText(inner))});
    }
    fail();
  }
  unexpected(DiagKind::ExpectedExpression);
}

// '[' expr {',' expr} ']' after a function's name, into e.args; returns
// the offset just past the ']'.
std::uint32_t Parser::parseArguments(int depth, Expr& e) {
  const Token open = tok_;
  enterBracket(depth, open);
  advance();
  for (;;) {
    ExprPtr arg = parseExpr(depth + 1);
    requireNumber(*arg);
    e.args.push_back(std::move(arg));
    if (tok_.kind != Tok::Comma) {
      break;
    }
    advance();
  }
  if (tok_.kind != Tok::RBracket) {
    rejectExponent();
    auto& d = diags_.report(DiagKind::ExpectedCloseBracket, tok_.range);
    d.fixIts.push_back({{tok_.range.begin, 0}, "]"});
    diags_.note(DiagKind::BracketOpenedHere, open.range);
    fail();
  }
  const std::uint32_t end = tok_.range.begin.offset + 1;
  advance();
  return end;
}

// function := NAME '[' expr {',' expr} ']' | 'ATAN' '[' expr ']' '/' '[' expr
// ']'
ExprPtr Parser::parseCall(int depth) {
  Token name = tok_;
  advance();
  if (tok_.kind != Tok::LBracket) {
    diags_.report(DiagKind::FunctionNeedsBracket, name.range, name.text,
                  name.text);
    noteParenthesis(name);
    fail();
  }
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Call;
  e->builtin = name.builtin;
  std::uint32_t end = parseArguments(depth, *e);
  // ATAN[a]/[b] is the two-sided arctangent, not a division (spec §3.3).
  if (name.builtin == Builtin::Atan && e->args.size() == 1 &&
      tok_.kind == Tok::Slash && peek().kind == Tok::LBracket) {
    advance();
    ExprPtr b = parseBracketed(depth);
    end = b->range.begin.offset + b->range.length;
    b->bracketed = false;
    e->args.push_back(std::move(b));
  }
  if (name.builtin == Builtin::Atan && e->args.size() == 2) {
    e->builtin = Builtin::Atan2;
  }
  int arity = builtinArity(e->builtin);
  if (static_cast<int>(e->args.size()) != arity) {
    diags_.report(DiagKind::FunctionArity, name.range, name.text, arity,
                  e->args.size());
    fail();
  }
  e->range = {name.range.begin, end - name.range.begin.offset};
  return e;
}

// The letters of PRM (three address letters to the lexer) before '['.
bool Parser::startsParameterRead(const Token& letter) const {
  const std::string_view text = sources_.text(letter.range.begin.file);
  const std::size_t at = letter.range.begin.offset;
  if (at + 4 > text.size() || text[at + 3] != '[') {
    return false;
  }
  std::string word(text.substr(at, 3));
  for (char& ch : word) {
    ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  }
  return word == "PRM";
}

// PRM[n], PRM[n, bit], PRM[n]/[axis], PRM[n, bit]/[axis]: like ATAN[a]/[b],
// a bracket after '/' is the axis, not a divisor.
ExprPtr Parser::parseParameterRead(int depth) {
  const Token name = tok_;
  advance(); // P
  advance(); // R
  advance(); // M
  auto e = std::make_unique<Expr>();
  e->kind = ExprKind::Parameter;
  std::uint32_t end = parseArguments(depth, *e);
  if (e->args.size() > 2) {
    diags_.report(DiagKind::FunctionArity, name.range, "PRM", 2,
                  e->args.size());
    fail();
  }
  e->parameterForm = e->args.size() == 2 ? MBRT_PARAMETER_BIT : 0;
  if (tok_.kind == Tok::Slash && peek().kind == Tok::LBracket) {
    advance();
    ExprPtr axis = parseBracketed(depth);
    end = axis->range.begin.offset + axis->range.length;
    axis->bracketed = false;
    e->args.push_back(std::move(axis));
    e->parameterForm |= MBRT_PARAMETER_AXIS;
  }
  e->range = {name.range.begin, end - name.range.begin.offset};
  return e;
}

} // namespace mbc::detail
