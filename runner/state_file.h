// `--state PATH`: what a machine keeps between runs. The nonvolatile
// variables #500-#999, the work offsets and the tool offsets, as JSON with
// the keys of a machine profile ("variables", "work_offsets",
// "tool_offsets"), so that a state file can also serve as a profile part,
// in the machine's unit, with the "series" and "unit" it is for.
#pragma once

#include <mbc/runtime.h>

#include <string>

namespace mbc::runner {

/// Replaces the context's nonvolatile variables and offsets by the file's
/// (what it leaves out is vacant or 0), through the runtime's writes so
/// that the flattened program gets them as G10 blocks. A missing file is an
/// empty state: true. False with `error` set when the file is unreadable
/// or malformed.
bool loadState(mbrt_ctx* ctx, const std::string& path, std::string& error);

/// Writes the context's state to `path` through a temporary file and a
/// rename: a reader sees the old file or the new one, never part of one.
bool saveState(mbrt_ctx* ctx, const std::string& path);

} // namespace mbc::runner
