// A whole file into a string, for programs, profiles, state files and
// tables.
#pragma once

#include <string>

namespace mbc {

/// Reads the file at `path` into `text`. Returns 0, or the errno of what
/// failed (ENOENT, EACCES, EISDIR for a directory, EIO...). Unlike reading
/// through a stream, an error in the middle of the file is reported, not
/// taken for its end, and std::bad_alloc reaches the caller.
int readFile(const std::string& path, std::string& text);

} // namespace mbc
