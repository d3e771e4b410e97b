// The programs a block calls by a constant P or a name (G65, G66, G66.1,
// M98, M198): what the program search path loads, and what the checks warn
// of when nothing defines them.
#pragma once

#include "frontend/ast.h"

#include <compare>
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

} // namespace mbc
