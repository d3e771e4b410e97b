// Completion (see completion.h).
#include "lsp/completion.h"

#include <mbc/arith.h>
#include <mbc/g_codes.h>
#include <mbc/sysvars.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "lsp/m_codes.h"

namespace mbc::lsp {

namespace {

constexpr int kFunctionItem = 3;
constexpr int kVariableItem = 6;
constexpr int kKeywordItem = 14;
constexpr int kReferenceItem = 18;

constexpr Builtin kBuiltins[] = {
#define BUILTIN(Id, Name, Arity) Builtin::Id,
#include <mbc/builtins.def>
};

/// "G01", "G54.1": a code as programs usually write it.
std::string writtenG(int tenths) {
  return tenths % 10 == 0 && tenths < 100 ? fmt::format("G{:02}", tenths / 10)
                                          : gCodeText(tenths);
}

bool startsWith(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() &&
         std::equal(prefix.begin(), prefix.end(), text.begin(),
                    [](char a, char b) {
                      return std::toupper(static_cast<unsigned char>(a)) ==
                             std::toupper(static_cast<unsigned char>(b));
                    });
}

} // namespace

std::vector<Completion> completionsAt(std::string_view text,
                                      std::uint32_t offset,
                                      const Program* program,
                                      char latheSystem) {
  std::vector<Completion> out;
  offset =
      std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text.size()));
  std::uint32_t lineStart = offset;
  while (lineStart > 0 && text[lineStart - 1] != '\n' &&
         text[lineStart - 1] != '\r') {
    --lineStart;
  }
  // The word being written: a letter or '#' and what follows it.
  std::uint32_t start = offset;
  while (start > lineStart &&
         (std::isdigit(static_cast<unsigned char>(text[start - 1])) ||
          text[start - 1] == '.')) {
    --start;
  }
  std::uint32_t letters = start;
  while (letters > lineStart &&
         std::isalpha(static_cast<unsigned char>(text[letters - 1]))) {
    --letters;
  }
  // GOTO100: the number alone is the word (GOTO is a keyword, not an
  // address).
  const bool gotoNumber =
      start - letters >= 4 && startsWith(text.substr(start - 4, 4), "GOTO");
  while (!gotoNumber && start > lineStart &&
         (std::isalpha(static_cast<unsigned char>(text[start - 1])) ||
          text[start - 1] == '#')) {
    --start;
    if (text[start] == '#') {
      break;
    }
  }
  const std::string_view word = text.substr(start, offset - start);
  const SourceRange replaced{{0, start}, offset - start};
  const std::string_view before = text.substr(lineStart, start - lineStart);
  const auto add = [&](std::string label, int kind, std::string detail) {
    if (startsWith(label, word)) {
      out.push_back({std::move(label), kind, std::move(detail), replaced});
    }
  };
  // GOTO 100: the labels of the program.
  std::string upper(before);
  for (char& c : upper) {
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  const std::size_t go = upper.rfind("GOTO");
  const bool afterGoto =
      go != std::string::npos &&
      upper.find_first_not_of(" \t", go + 4) == std::string::npos;
  if (afterGoto || (word.empty() && upper.ends_with("GOTO"))) {
    if (program != nullptr) {
      for (const Block& b : program->blocks) {
        if (b.seq >= 0) {
          add(std::to_string(b.seq), kReferenceItem,
              fmt::format("N{} of {}", b.seq, program->name));
        }
      }
    }
    return out;
  }
  if (word.starts_with("#")) {
    for (const SystemVariableFacts& row : systemVariableRows()) {
      if (row.readable) {
        add(fmt::format("#{}", row.first), kVariableItem,
            row.first == row.last
                ? std::string(row.meaning)
                : fmt::format("#{}-#{}: {}", row.first, row.last, row.meaning));
      }
    }
    return out;
  }
  if (!word.empty() &&
      std::toupper(static_cast<unsigned char>(word[0])) == 'G') {
    for (const auto& [tenths, facts] :
         gCodeList(latheSystem != 0 ? latheSystem : 'M')) {
      add(writtenG(tenths), kKeywordItem,
          facts.modelled
              ? facts.name
              : fmt::format("{} (mbc does not execute it yet)", facts.name));
    }
    return out;
  }
  if (!word.empty() &&
      std::toupper(static_cast<unsigned char>(word[0])) == 'M') {
    for (const MCodeText& m : kMCodes) {
      add(fmt::format("M{:02}", m.code), kKeywordItem, m.name);
    }
  }
  // Functions, where an expression is: inside brackets.
  const auto open = std::count(before.begin(), before.end(), '[') -
                    std::count(before.begin(), before.end(), ']');
  if (open > 0 || word.size() >= 2) {
    for (const Builtin fn : kBuiltins) {
      const std::string name = builtinName(fn);
      const bool said = std::any_of(out.begin(), out.end(), [&](auto& c) {
        return c.label == name; // ATAN[a] and ATAN[a,b]
      });
      if (!said) {
        add(name, kFunctionItem, "a function of Custom Macro B");
      }
    }
  }
  return out;
}

} // namespace mbc::lsp
