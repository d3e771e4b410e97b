// The toolpath as JSON lines: one object per executed motion, the format
// `mbc run --toolpath` writes and the golden tests compare byte for byte.
#pragma once

#include <mbc/runtime.h>

#include <cstddef>
#include <string>

namespace mbc {

/// One motion as a JSON object followed by '\n', keys in this order:
/// "motion" ("rapid", "linear", "cw", "ccw"), one key per axis in lower case
/// (workpiece frame), "m" + each axis (machine coordinates of the control
/// point), "f" (not for rapids), for arcs "c" + each plane axis in lower case,
/// then "line" and "prog". Coordinates have at most m.decimals digits with
/// trailing zeros dropped; independent of the C locale.
std::string toolpathJsonLine(const mbrt_motion& m);

/// toolpathJsonLine appended to `out`.
void appendToolpathJson(std::string& out, const mbrt_motion& m);

/// At least the bytes of toolpathJsonLine(m), found without formatting it:
/// what a writer on another thread counts against the output limit.
std::size_t toolpathJsonBound(const mbrt_motion& m);

} // namespace mbc
