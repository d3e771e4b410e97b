// The C entry points of compiled code: which programs get one and their
// names, shared by the emitter and the C header (no LLVM here).
#pragma once

#include "ir/ir.h"

#include <string>

namespace mbc::codegen {

/// Whether a program gets a C entry point: O-numbered ones do; a program
/// known by name only is found with mbrt_find_program.
bool hasEntryPoint(const ir::Function& f);

/// The C name of a numbered program's entry point ("mbc_O1000").
std::string entryPointName(int number);

} // namespace mbc::codegen
