// The program search path (see program_search.h).
#include "toolchain/program_search.h"

#include <mbc/addresses.h>
#include <mbc/calling_codes.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace mbc::toolchain {

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

/// Whether a literal word of the block is a code `is` accepts.
bool hasCode(const std::vector<Word>& words, bool (*is)(char, double)) {
  for (const Word& w : words) {
    if (w.value->kind == ExprKind::Number && is(w.letter, w.value->number)) {
      return true;
    }
  }
  return false;
}

CalledProgram numbered(int number) {
  return {number, programName(number)};
}

/// The programs an NC block calls by P or name: M98/M198 P (and a 4-digit
/// control's reading), G66/G66.1 P.
void calledByWords(const std::vector<Word>& words,
                   std::set<CalledProgram>& out) {
  const Word* p = findWord(words, 'P');
  if (p != nullptr && !p->calledName.empty()) {
    out.insert({-1, p->calledName});
    return;
  }
  const std::optional<int> number = p ? literal(*p) : std::nullopt;
  if (!number) {
    return;
  }
  if (hasCode(words, isSubprogramCall)) {
    out.insert(numbered(*number));
    if (*number > kMaxProgramNumber4Digits && !findWord(words, 'L')) {
      out.insert(numbered(*number % (kMaxProgramNumber4Digits + 1)));
    }
  } else if (hasCode(words, isMacroCall)) { // G66, G66.1: G65 is no NC block
    out.insert(numbered(*number));
  }
}

} // namespace

std::set<CalledProgram> missingCalledPrograms(const Unit& unit) {
  std::set<CalledProgram> called;
  for (const Program& program : unit.programs) {
    for (const Block& b : program.blocks) {
      const Stmt& s = b.stmt;
      if (s.kind == StmtKind::MacroCall && !s.calledName.empty()) {
        called.insert({-1, s.calledName});
      } else if (s.kind == StmtKind::MacroCall && s.program &&
                 s.program->kind == ExprKind::Number) {
        if (const std::optional<int> number =
                programNumber(s.program->number)) {
          called.insert(numbered(*number));
        }
      } else if (s.kind == StmtKind::Nc) {
        calledByWords(s.words, called);
      }
    }
  }
  std::erase_if(called, [&unit](const CalledProgram& c) {
    return std::any_of(
        unit.programs.begin(), unit.programs.end(), [&c](const Program& p) {
          return c.number >= 0 ? p.number == c.number : p.name == c.name;
        });
  });
  return called;
}

std::optional<std::string>
findProgramFile(const CalledProgram& program,
                const std::vector<std::string>& dirs) {
  std::vector<std::string> stems;
  if (program.number >= 0) {
    const int n = program.number;
    stems = {fmt::format("O{}", n),     fmt::format("O{:04d}", n),
             fmt::format("O{:08d}", n), fmt::format("o{}", n),
             fmt::format("{}", n),      fmt::format("{:04d}", n)};
  } else {
    const std::string name = program.name.substr(1, program.name.size() - 2);
    std::string lower = name;
    for (char& c : lower) {
      c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
    }
    stems = {name, lower};
  }
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

} // namespace mbc::toolchain
