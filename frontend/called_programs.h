// The programs a block calls by a constant P or a name (G65, G66, G66.1,
// M98, M198): what the program search path loads, and what the checks warn
// of when nothing defines them.
#pragma once

#include "frontend/ast.h"

#include <compare>
#include <optional>
#include <string>
#include <vector>

namespace mbc {

/// A program a call names: by O number, or by name (`number` -1).
struct CalledProgram {
  int number = -1;
  std::string name; // "O1234" or "<DRILL>"

  auto operator<=>(const CalledProgram&) const = default;
};

/// One block's call of a constant program: the word or expression that
/// names it and the programs it may mean. An M98 P of more than four digits
/// without L means its low four digits too, the program a 4-digit control
/// calls (so many times as the digits above say).
struct ProgramCall {
  SourceRange range;
  std::vector<CalledProgram> programs;
};

/// The block's call of a constant program or a name, if it makes one.
std::optional<ProgramCall> programCallOf(const Stmt& s);

/// The argument words of a G65 (its words) or a G66 (its words but G, P
/// and L); none for other statements.
std::vector<const Word*> callArguments(const Stmt& s);

/// The local each argument sets, in specification I or, for I, J and K,
/// in the sets of specification II (spec §5.2-5.4); 0 for a letter that is
/// no argument or an eleventh set.
std::vector<int> argumentLocals(const std::vector<const Word*>& args);

/// Per program of the unit, whether it is a main program: no program of
/// the unit calls it by a constant P or name, and it is written to end the
/// run (it has an M02 or M30) or has no O number.
std::vector<bool> mainPrograms(const Unit& unit);

} // namespace mbc
