// The programs a block calls (see called_programs.h).
#include "frontend/called_programs.h"

#include <mbc/addresses.h>
#include <mbc/calling_codes.h>

#include <algorithm>
#include <set>

namespace mbc {

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

/// An NC block's call by P or name: M98/M198 P (and a 4-digit control's
/// reading), G66/G66.1 P.
std::optional<ProgramCall> calledByWords(const std::vector<Word>& words) {
  const Word* p = findWord(words, 'P');
  if (p == nullptr) {
    return std::nullopt;
  }
  if (!p->calledName.empty()) {
    return ProgramCall{p->range, {{-1, p->calledName}}};
  }
  const std::optional<int> number = literal(*p);
  if (!number) {
    return std::nullopt;
  }
  if (hasCode(words, isSubprogramCall)) {
    ProgramCall call{p->range, {numbered(*number)}};
    if (*number > kMaxProgramNumber4Digits && !findWord(words, 'L')) {
      call.programs.push_back(
          numbered(*number % (kMaxProgramNumber4Digits + 1)));
    }
    return call;
  }
  if (hasCode(words, isMacroCall)) { // G66, G66.1: G65 is no NC block
    return ProgramCall{p->range, {numbered(*number)}};
  }
  return std::nullopt;
}

} // namespace

std::optional<ProgramCall> programCallOf(const Stmt& s) {
  if (s.kind == StmtKind::MacroCall && !s.calledName.empty()) {
    return ProgramCall{s.program ? s.program->range : s.range,
                       {{-1, s.calledName}}};
  }
  if (s.kind == StmtKind::MacroCall && s.program) {
    if (s.program->kind != ExprKind::Number) {
      return std::nullopt;
    }
    const std::optional<int> number = programNumber(s.program->number);
    return number ? std::optional(
                        ProgramCall{s.program->range, {numbered(*number)}})
                  : std::nullopt;
  }
  return s.kind == StmtKind::Nc ? calledByWords(s.words) : std::nullopt;
}

std::vector<const Word*> callArguments(const Stmt& s) {
  std::vector<const Word*> args;
  if (s.kind == StmtKind::MacroCall) {
    for (const Word& w : s.words) {
      args.push_back(&w);
    }
  } else if (s.kind == StmtKind::Nc &&
             std::any_of(s.words.begin(), s.words.end(), [](const Word& w) {
               return w.letter == 'G' && w.value->kind == ExprKind::Number &&
                      w.value->number == 66;
             })) {
    for (const Word& w : s.words) {
      if (w.letter != 'G' && w.letter != 'P' && w.letter != 'L') {
        args.push_back(&w);
      }
    }
  }
  return args;
}

std::vector<int> argumentLocals(const std::vector<const Word*>& args) {
  std::vector<int> locals;
  IjkSets sets;
  for (const Word* w : args) {
    locals.push_back(nextArgumentLocal(w->letter, sets));
  }
  return locals;
}

std::vector<bool> mainPrograms(const Unit& unit) {
  std::set<std::string, std::less<>> called;
  for (const Program& p : unit.programs) {
    for (const Block& b : p.blocks) {
      if (const std::optional<ProgramCall> call = programCallOf(b.stmt)) {
        for (const CalledProgram& callee : call->programs) {
          called.insert(callee.name);
        }
      }
    }
  }
  std::vector<bool> main;
  for (const Program& p : unit.programs) {
    const bool ends =
        std::any_of(p.blocks.begin(), p.blocks.end(), [](const Block& b) {
          return b.stmt.kind == StmtKind::Nc &&
                 hasCode(b.stmt.words, [](char letter, double value) {
                   return letter == 'M' && (value == 2 || value == 30);
                 });
        });
    main.push_back(!called.contains(p.name) && (p.number < 0 || ends));
  }
  return main;
}

} // namespace mbc
