// The program a run starts with (see main_program.h).
#include "toolchain/main_program.h"

#include <mbc/addresses.h>

#include <fmt/format.h>

#include <vector>

#include "toolchain/closest_match.h"

namespace mbc::toolchain {

int findMain(const Unit& unit, const std::string& wanted) {
  if (unit.programs.empty()) {
    return -1;
  }
  if (wanted.empty()) {
    return 0;
  }
  for (int i = 0; i < static_cast<int>(unit.programs.size()); ++i) {
    const Program& p = unit.programs[i];
    if (namesProgram(p.name, p.number, wanted)) {
      return i;
    }
  }
  return -1;
}

std::string missingMainMessage(const Unit& unit, const std::string& wanted) {
  std::vector<std::string> names;
  for (const Program& p : unit.programs) {
    names.push_back(p.name);
  }
  const std::string guess = closestMatch(wanted, names);
  return fmt::format(
      "no program {} in the input{}", wanted,
      guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess));
}

} // namespace mbc::toolchain
