// The program a run starts with: the one `--main` names, or the first of
// the input. `mbc run` and `mbc check --arg` find it the same way.
#pragma once

#include "frontend/ast.h"

#include <string>

namespace mbc::toolchain {

/// The index in unit.programs of the program `wanted` names ("O9001",
/// "9001", "<DRILL>"), or of the first program when `wanted` is empty; -1
/// when there is none.
int findMain(const Unit& unit, const std::string& wanted);

/// "no program 9002 in the input; did you mean 'O9001'?"
std::string missingMainMessage(const Unit& unit, const std::string& wanted);

} // namespace mbc::toolchain
