// Reading, parsing and checking the input files: the front half shared by
// every mbc command.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"
#include "frontend/source.h"

#include <string>
#include <vector>

namespace mbc::driver {

struct CompiledUnit {
  SourceManager sources;
  Unit unit;
};

/// Loads and checks the files. Diagnostics go to standard error. Returns
/// false when a file could not be read, or when there were errors and
/// `errors` is ErrorMode::Refuse; under ErrorMode::Alarm errors print as
/// warnings and each block that has one raises its alarm when it runs.
/// `machinePath`: the --machine profile, if any, which the checks defer to.
bool loadUnit(const std::vector<std::string>& files, bool checkWarnings,
              CompiledUnit& out, const std::string& machinePath = {},
              ErrorMode errors = ErrorMode::Refuse);

} // namespace mbc::driver
