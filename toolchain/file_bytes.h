// Whole writes through a file descriptor (a temporary file, a memory
// file), retried after signals. Whole reads are mbc::readFile.
#pragma once

#include <cstddef>

namespace mbc::toolchain {

/// Writes all `size` bytes; false on an error.
bool writeAll(int fd, const char* data, std::size_t size);

} // namespace mbc::toolchain
