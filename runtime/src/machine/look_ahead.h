// The look-ahead, AI contour control, smoothing and servo switches of a
// 0i-F / 30i-B: G05 P10000/P0, G05.1 Q0-Q3, G05.4 Q0/Q1 and G08 P1/P0. They
// are group 00 codes (no #4001+ variable reads them) that change feed and
// acceleration, not the path: mbc checks their words and moves as
// programmed.
#pragma once

#include <optional>

#include "context.h"

namespace mbc::rt {

/// The words such a block switches with, as written.
struct LookAheadWords {
  std::optional<double> p;
  std::optional<double> q;
};

/// One look-ahead switch. The axis words of G05.1 Q2/Q3 name the axes to
/// smooth: they are no move.
mbrt_status switchLookAhead(mbrt_ctx& ctx, int tenths,
                            const LookAheadWords& words);

} // namespace mbc::rt
