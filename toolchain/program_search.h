// The program search path: a main program finds the subprograms and macros
// it calls in files beside it or in -I directories (O1234.nc, 1234.nc,
// DRILL.nc...),
// as a control finds them in its memory or on a data server.
#pragma once

#include "frontend/ast.h"
#include "frontend/called_programs.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mbc::toolchain {

/// The programs the unit calls with a constant P or a name (G65, G66,
/// G66.1, M98, M198: programCallOf) and does not define.
std::set<CalledProgram> missingCalledPrograms(const Unit& unit);

/// The first file in `dirs` named for the program: O1234.nc, o1234.nc,
/// 1234.nc, O00001234.nc for a number, DRILL.nc or drill.nc for <DRILL>,
/// with or without .nc.
std::optional<std::string>
findProgramFile(const CalledProgram& program,
                const std::vector<std::string>& dirs);

} // namespace mbc::toolchain
