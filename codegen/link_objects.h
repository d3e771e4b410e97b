// One relocatable object from several, with the system linker: object
// files made in parts (object_file.cpp) must still be one `-o OUT.o`.
#pragma once

#include <string>
#include <vector>

namespace mbc::codegen {

/// Runs `ld -r -o output inputs...` (binutils, which the C++ compiler
/// brings). False with the reason in `error` when it cannot run or fails.
bool linkRelocatable(const std::vector<std::string>& inputs,
                     const std::string& output, std::string& error);

} // namespace mbc::codegen
