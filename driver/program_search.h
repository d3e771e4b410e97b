// The program search path: a main program finds the subprograms and macros
// it calls in files beside it or in -I directories (O1234.nc, 1234.nc...),
// as a control finds them in its memory or on a data server.
#pragma once

#include "frontend/ast.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mbc::driver {

/// The numbers of the programs the unit calls with a constant P (G65, G66,
/// G66.1, M98, M198) and does not define. An M98 P of more than four digits
/// without L also names its low four digits, the program a 4-digit control
/// calls.
std::set<int> missingCalledPrograms(const Unit& unit);

/// The first file in `dirs` named for program `number` (O1234.nc, o1234.nc,
/// 1234.nc, O00001234.nc, with or without .nc), if any.
std::optional<std::string>
findProgramFile(int number, const std::vector<std::string>& dirs);

} // namespace mbc::driver
