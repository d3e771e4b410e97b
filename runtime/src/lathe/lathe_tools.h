// A lathe's tool offsets in motion: the T code Ttt oo selects tool tt and
// offset oo (parameter 5002 all 0: two offset digits, the geometry offset of
// the offset number). The geometry offset shifts the coordinate system (the
// tool stays, the position it shows changes); the wear offset moves the tool,
// in the T code's block. Offset 0 cancels the wear offset; the geometry
// offset stays (5002#5 LGC = 0). G10 P writes the offsets.
#pragma once

#include "frame_words.h"

namespace mbc::rt {

/// The offsets of a T code's offset number; `moved` tells that the wear
/// offset changed, so that a block without motion moves by it.
mbrt_status selectLatheOffset(mbrt_ctx& ctx, double t, bool* moved);

/// G10 P X Y Z R Q (P n: wear, 10000 + n: geometry) or with U V W C, which
/// add to the offset.
mbrt_status writeLatheOffsets(mbrt_ctx& ctx, const FrameWords& words);

} // namespace mbc::rt
