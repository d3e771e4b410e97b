#include "codegen/entry_points.h"

#include <mbc/addresses.h>

#include <fmt/format.h>

namespace mbc::codegen {

bool hasEntryPoint(const ir::Function& f) {
  return f.number >= 0 && !isNamedProgramNumber(f.number);
}

std::string entryPointName(int number) {
  return fmt::format("mbc_O{}", number);
}

} // namespace mbc::codegen
