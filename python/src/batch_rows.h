// mbc.batch's C++ side: the rows on worker threads, each thread with a
// context of its own that is reset before every row (as `mbc batch` does),
// all sharing the one compiled program; results in table order.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "program_run.h"

namespace mbc::python {

/// Runs every row; `profile` is the machine's JSON (nullptr: the built-in
/// mill). Needs no Python. False with the reason in `error` when a context
/// cannot be made. A signal (Ctrl-C) stops the rows going on (their status
/// is MBRT_ALARM_Interrupted) and starts no more: the rows it never
/// started have no output (nullptr), the finished ones keep theirs.
bool runRows(const CompiledProgram& program, const std::string* profile,
             const std::vector<RunRequest>& rows, unsigned threads,
             std::vector<std::unique_ptr<RunOutput>>& out, std::string& error);

} // namespace mbc::python
