// mbc check's vacant reads: a local that reaches an address word vacant on
// every path, or on some (the word is dropped, or reads 0), and a macro's
// local that no call of it passes, read without a test against #0. A
// forward analysis over each program's blocks, in the habits of clang's
// -Wuninitialized and -Wsometimes-uninitialized.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <cstdint>

namespace mbc {

/// Warns of the vacant reads of every program of the unit, with notes on
/// where the vacancy comes from and the condition of the path that keeps
/// it. Only what is sure on a path is said: a local is vacant at the start
/// of a main program (one no program of the unit calls that ends with M02
/// or M30), where a program writes `#n = #0`, and at the start of a macro
/// whose calls in the unit all leave its letter out. After a call that
/// may write the locals, and where code elsewhere may jump in, nothing is
/// known. Needs the GOTO targets and loops the semantic checks resolve.
/// `arguments`: the program run as the main one with arguments (mbc check
/// --arg), whose locals they set are not vacant.
struct MainArguments {
  int program = -1;         // index in the unit
  std::uint64_t locals = 0; // bit n - 1 for #n
};

void warnVacantReads(const Unit& unit, DiagnosticEngine& diags,
                     const MainArguments& arguments);

} // namespace mbc
