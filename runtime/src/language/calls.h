// Calls (calls.cpp): what the rest of the language needs of them.
#pragma once

#include "context.h"

namespace mbc::rt {

/// Counts per unit of the address that sets local `local` (1-33) from a
/// literal without decimal point: ADP gives the literal back with it.
double argumentScale(const mbrt_ctx& ctx, int local);

} // namespace mbc::rt
