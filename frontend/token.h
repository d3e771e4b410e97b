// Tokens of Custom Macro B. Words are context-dependent (a letter is an
// address unless it starts a keyword), so the lexer is pulled by the parser.
#pragma once

#include "frontend/source.h"
#include <mbc/arith.h>

#include <string>

namespace mbc {

enum class Tok {
  EndOfBlock, // LF, or ';' (the rest of its line is a comment)
  EndOfFile,
  Percent,
  Number,
  Hash,
  LBracket,
  RBracket,
  Comma,
  Plus,
  Minus,
  Star,
  Slash,
  Equal,
  Letter,      // an address letter; text holds it
  ProgramName, // <NAME>
  Comment,     // ( ... ); text holds the inside
  Keyword,
  Function,
  PrintText, // DPRNT/BPRNT literal text (only in print mode)
  Invalid,
};

enum class Keyword {
  If,
  Goto,
  Then,
  While,
  Do,
  End,
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  And,
  Or,
  Xor,
  Mod,
  Dprnt,
  Bprnt,
  Popen,
  Pclos,
};

struct Token {
  Tok kind = Tok::Invalid;
  SourceRange range;
  std::string text;  // letter, comment text, name, print text
  double number = 0; // Number
  bool hasDecimal = false;
  Keyword keyword = Keyword::If;
  Builtin builtin = Builtin::Sin;
};

/// A human name for diagnostics ("']'", "end of block", "address X").
std::string describe(const Token& t);

} // namespace mbc
