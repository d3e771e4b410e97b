// The program search path (see program_search.h).
#include "driver/program_search.h"

#include <mbc/addresses.h>

#include <fmt/format.h>

#include <filesystem>

namespace mbc::driver {

namespace {

std::optional<int> programNumber(double v) {
  if (v < 1 || v > kMaxProgramNumber || v != static_cast<int>(v)) {
    return std::nullopt;
  }
  return static_cast<int>(v);
}

/// The value of a word written as a literal program number, if it is one.
std::optional<int> literal(const Word& w) {
  if (w.kind != WordKind::IntLiteral && w.kind != WordKind::DecLiteral) {
    return std::nullopt;
  }
  return programNumber(w.value->number);
}

const Word* findWord(const std::vector<Word>& words, char letter) {
  for (const Word& w : words) {
    if (w.letter == letter) {
      return &w;
    }
  }
  return nullptr;
}

bool hasCode(const std::vector<Word>& words, char letter, double value) {
  for (const Word& w : words) {
    if (w.letter == letter && w.value->kind == ExprKind::Number &&
        w.value->number == value) {
      return true;
    }
  }
  return false;
}

/// The programs an NC block calls by P: M98/M198 P (and a 4-digit
/// control's reading), G66/G66.1 P.
void calledByWords(const std::vector<Word>& words, std::set<int>& out) {
  const Word* p = findWord(words, 'P');
  const std::optional<int> number = p ? literal(*p) : std::nullopt;
  if (!number) {
    return;
  }
  if (hasCode(words, 'M', 98) || hasCode(words, 'M', 198)) {
    out.insert(*number);
    if (*number > kMaxProgramNumber4Digits && !findWord(words, 'L')) {
      out.insert(*number % (kMaxProgramNumber4Digits + 1));
    }
  } else if (hasCode(words, 'G', 66) || hasCode(words, 'G', 66.1)) {
    out.insert(*number);
  }
}

} // namespace

std::set<int> missingCalledPrograms(const Unit& unit) {
  std::set<int> called;
  for (const Program& program : unit.programs) {
    for (const Block& b : program.blocks) {
      const Stmt& s = b.stmt;
      if (s.kind == StmtKind::MacroCall && s.program &&
          s.program->kind == ExprKind::Number) {
        if (const std::optional<int> number =
                programNumber(s.program->number)) {
          called.insert(*number);
        }
      } else if (s.kind == StmtKind::Nc) {
        calledByWords(s.words, called);
      }
    }
  }
  for (const Program& program : unit.programs) {
    called.erase(program.number);
  }
  return called;
}

std::optional<std::string>
findProgramFile(int number, const std::vector<std::string>& dirs) {
  const std::vector<std::string> stems = {
      fmt::format("O{}", number),     fmt::format("O{:04d}", number),
      fmt::format("O{:08d}", number), fmt::format("o{}", number),
      fmt::format("{}", number),      fmt::format("{:04d}", number)};
  for (const std::string& dir : dirs) {
    for (const std::string& stem : stems) {
      for (const char* extension : {".nc", ".NC", ""}) {
        const std::filesystem::path path =
            std::filesystem::path(dir) / (stem + extension);
        std::error_code error;
        if (std::filesystem::is_regular_file(path, error)) {
          return path.string();
        }
      }
    }
  }
  return std::nullopt;
}

} // namespace mbc::driver
