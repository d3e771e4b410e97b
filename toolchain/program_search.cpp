// The program search path (see program_search.h).
#include "toolchain/program_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace mbc::toolchain {

std::set<CalledProgram> missingCalledPrograms(const Unit& unit) {
  std::set<CalledProgram> called;
  for (const Program& program : unit.programs) {
    for (const Block& b : program.blocks) {
      if (const std::optional<ProgramCall> call = programCallOf(b.stmt)) {
        called.insert(call->programs.begin(), call->programs.end());
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
