// Whole reads and writes through file descriptors, retried after signals.
#pragma once

#include <cstddef>
#include <string>

namespace mbc::driver {

/// The file's bytes, all of them; false on an error.
bool readAll(int fd, std::string& out);

/// Writes all `size` bytes; false on an error.
bool writeAll(int fd, const char* data, std::size_t size);

} // namespace mbc::driver
