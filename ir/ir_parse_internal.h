// Internals of the IR text parser shared by ir_parser.cpp (functions and
// blocks) and ir_parse_inst.cpp (one instruction): a character cursor that
// knows line and column, and the error it throws.
#pragma once

#include "ir/ir.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace mbc::ir::parse {

/// Value and block ids above this are rejected: insts is sized by the
/// largest id, so a typo must not allocate gigabytes.
inline constexpr std::uint32_t kMaxId = 1U << 22;

struct TextPos {
  std::uint32_t line = 1;
  std::uint32_t col = 1; // bytes
};

/// Thrown by Cursor::fail and caught by parseModule.
struct ParseError {
  TextPos pos;
  std::string message;
};

/// Reads the text character by character. Newlines end instructions, so
/// they are never skipped implicitly: only skipLines crosses them.
class Cursor {
public:
  explicit Cursor(std::string_view text) : text_(text) {}

  /// Skips spaces, tabs and a `;` comment, up to (not over) a newline.
  void skipBlanks();
  /// Skips blanks, comments and newlines.
  void skipLines();
  bool atEnd();
  /// True at a newline or the end of the text (after blanks).
  bool atEol();
  /// Consumes the end of the line; anything else there is an error.
  void endLine();
  /// Consumes `c` if it comes next (after blanks).
  bool accept(char c);
  void expect(char c);
  /// The next character after blanks, '\0' at the end.
  char peek();
  /// Whether `bN:` comes next.
  bool atLabel();

  /// [A-Za-z0-9_.]+, `what` names it in the error.
  std::string_view word(const char* what);
  /// Everything up to `close` (for `<NAME>`); the delimiters are consumed.
  std::string_view delimited(char open, char close);
  std::int64_t integer(const char* what);
  /// An integer in lo..hi, else "WHAT out of range".
  std::int64_t integer(const char* what, std::int64_t lo, std::int64_t hi);
  double number();
  std::string string();
  ValueId value();
  BlockId block();

  TextPos pos() const { return pos_; }

  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] static void failAt(TextPos pos, const std::string& message);

private:
  char current() const { return i_ < text_.size() ? text_[i_] : '\0'; }

  void advance();
  std::uint32_t id(char prefix, const char* what);

  std::string_view text_;
  std::size_t i_ = 0;
  TextPos pos_;
};

struct ParsedInst {
  TextPos pos;
  Inst inst;
  bool hasId = false;
  ValueId id = 0;
  bool hasLine = false; // an explicit `!LINE`
};

/// Parses one instruction line, `[%N =] mnemonic operands [!LINE]`, and
/// consumes its newline. Strings go into m.strings.
ParsedInst parseInst(Cursor& c, Module& m);

} // namespace mbc::ir::parse
