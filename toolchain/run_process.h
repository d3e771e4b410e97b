// Running another program (the linker) and waiting for it.
#pragma once

#include <string>
#include <vector>

namespace mbc::toolchain {

/// Runs args[0] (searched in PATH) with the rest as its arguments and
/// waits: its exit status, or -1 when it could not run or did not exit.
int runProcess(const std::vector<std::string>& args);

} // namespace mbc::toolchain
