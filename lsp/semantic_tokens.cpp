// Semantic tokens (see semantic_tokens.h).
#include "lsp/semantic_tokens.h"

#include "frontend/diagnostics.h"
#include "frontend/lexer.h"
#include <mbc/limits.h>
#include <mbc/sysvars.h>

#include <optional>

namespace mbc::lsp {

namespace {

enum Type {
  kKeyword,
  kVariable,
  kNumber,
  kComment,
  kFunction,
  kProperty,
  kNamespace,
  kOperator,
  kString,
  kLabel, // enumMember
};

constexpr int kReadonly = 1;
constexpr int kDefaultLibrary = 2;

/// The class of a letter followed by its number: codes, labels, programs
/// and the other addresses.
int letterType(char letter) {
  switch (letter) {
    case 'G':
    case 'M':
      return kKeyword;
    case 'N':
      return kLabel;
    case 'O':
      return kNamespace;
    default:
      return kProperty;
  }
}

/// The class of a letter or '#', alone or with its number.
int typeOf(const Token& t) {
  return t.kind == Tok::Hash ? kVariable
                             : letterType(t.text.empty() ? 0 : t.text[0]);
}

struct Class {
  Tok kind;
  int type;
  int modifiers;
};

/// The tokens that are their own class (a letter or '#' takes its number's).
constexpr Class kClasses[] = {
    {Tok::Number, kNumber, 0},
    {Tok::Comment, kComment, 0},
    {Tok::Keyword, kKeyword, 0},
    {Tok::Function, kFunction, kDefaultLibrary},
    {Tok::ProgramName, kNamespace, 0},

    {Tok::Plus, kOperator, 0},
    {Tok::Minus, kOperator, 0},
    {Tok::Star, kOperator, 0},
    {Tok::Slash, kOperator, 0},
    {Tok::Equal, kOperator, 0},
    {Tok::PrintText, kString, 0},
};

int variableModifiers(double number) {
  const auto n = static_cast<int>(number);
  if (n == number && n > kLastNonvolatile) {
    const auto facts = systemVariableFacts(n);
    return kDefaultLibrary | (facts && !facts->writable ? kReadonly : 0);
  }
  return n == 0 ? kReadonly : 0;
}

} // namespace

std::vector<SemanticToken> semanticTokens(const SourceManager& sources,
                                          std::uint32_t file) {
  std::vector<SemanticToken> out;
  DiagnosticEngine quiet(sources);
  Lexer lexer(sources, file, quiet);
  const auto add = [&](const SourceRange& r, int type, int modifiers = 0) {
    if (r.length > 0) {
      out.push_back({r.begin.offset, r.length, type, modifiers});
    }
  };
  // A letter or '#' waits for its number, to make one token of both.
  std::optional<Token> pending;
  // DPRNT and BPRNT lex their text in a mode of its own, as the parser
  // does: after the keyword the '[' that opens it, then text and
  // variables, each variable with its format in brackets ('#1[53]', two
  // bracket pairs for '#[...][53]'), to the closing ']'.
  enum class Mode {
    Normal,
    PrintOpen,
    Print,
    PrintVariable
  } mode = Mode::Normal;
  int depth = 0;
  int pairsLeft = 0;
  for (std::size_t guard = 0; guard < (1u << 24); ++guard) {
    Token t = mode == Mode::Print ? lexer.nextPrint() : lexer.next();
    if (t.kind == Tok::EndOfFile) {
      break;
    }
    switch (mode) {
      case Mode::Normal:
        if (t.kind == Tok::Keyword &&
            (t.keyword == Keyword::Dprnt || t.keyword == Keyword::Bprnt)) {
          mode = Mode::PrintOpen;
        }
        break;
      case Mode::PrintOpen:
        mode = t.kind == Tok::LBracket ? Mode::Print : Mode::Normal;
        break;
      case Mode::Print:
        if (t.kind == Tok::Hash) {
          mode = Mode::PrintVariable;
          pairsLeft = 0;
        } else if (t.kind == Tok::RBracket || t.kind == Tok::EndOfBlock) {
          mode = Mode::Normal;
        }
        break;
      case Mode::PrintVariable:
        if (pairsLeft == 0) {
          pairsLeft = t.kind == Tok::LBracket ? 2 : 1; // #[...][53] or #1[53]
        }
        depth += t.kind == Tok::LBracket ? 1 : t.kind == Tok::RBracket ? -1 : 0;
        if (t.kind == Tok::RBracket && depth == 0 && --pairsLeft == 0) {
          mode = Mode::Print;
        }
        if (t.kind == Tok::EndOfBlock) {
          mode = Mode::Normal;
          depth = 0;
        }
        break;
    }
    if (pending) {
      const Token first = *pending;
      pending.reset();
      if (t.kind == Tok::Number) {
        const SourceRange both{first.range.begin, t.range.begin.offset +
                                                      t.range.length -
                                                      first.range.begin.offset};
        add(both, typeOf(first),
            first.kind == Tok::Hash ? variableModifiers(t.number) : 0);
        continue;
      }
      add(first.range, typeOf(first));
    }
    if (t.kind == Tok::Letter || t.kind == Tok::Hash) {
      pending = t;
      continue;
    }
    for (const auto& [kind, type, modifiers] : kClasses) {
      if (t.kind == kind) {
        add(t.range, type, modifiers);
      }
    }
  }
  if (pending) {
    add(pending->range, typeOf(*pending));
  }
  return out;
}

} // namespace mbc::lsp
