// A G word's value as the G code table reads it (tables/g_codes.h), for
// the block's decoding and the flattened program alike.
#pragma once

#include <mbc/arith.h>
#include <mbc/value.h>

namespace mbc::rt {

/// A G word's value in tenths (G54.1 is 541), rounded as the control reads
/// it; a vacant value counts 0, as in an expression.
inline double gWordTenths(Num value) {
  return roundHalfAway(numeric(value) * 10.0);
}

} // namespace mbc::rt
