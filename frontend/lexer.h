// The Macro B lexer: blocks end at LF (CR is ignored) or at ';' (the rest of
// the line is a comment), spaces are ignored between tokens and inside
// numbers, lower case reads as upper case, comments are tokens so that
// #3000/#3006 can take their message from them.
#pragma once

#include "frontend/diagnostics.h"
#include "frontend/token.h"

namespace mbc {

class Lexer {
public:
  Lexer(const SourceManager& sources, std::uint32_t file,
        DiagnosticEngine& diags);

  /// The next token in normal mode.
  Token next();
  /// The next token inside DPRNT[...]: literal text runs become PrintText;
  /// '#', '[', ']' and the end of the block are lexed as usual.
  Token nextPrint();
  /// Skips to the end of the current block (error recovery).
  void skipBlock();

  /// True once the closing '%' (or the end of the file) was reached.
  bool atEnd() const { return pos_ >= end_; }

private:
  Token make(Tok kind, std::uint32_t begin);
  Token lexNumber(std::uint32_t begin);
  void skipNumberRest();
  Token lexWord(std::uint32_t begin);
  Token lexComment(std::uint32_t begin);
  Token lexSpecial(std::uint32_t begin);
  Token lexNonAscii(std::uint32_t begin);
  void skipSpaces();
  bool isLoneCr(std::uint32_t i) const;
  void findTextBounds();
  std::size_t findClosingPercent(std::uint32_t from) const;
  char upperAt(std::uint32_t i);

  const SourceManager& sources_;
  std::uint32_t file_;
  DiagnosticEngine& diags_;
  std::string_view text_;
  std::uint32_t pos_ = 0;
  std::uint32_t end_ = 0;
  bool warnedLowerCase_ = false;
};

} // namespace mbc
