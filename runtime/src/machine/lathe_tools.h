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

/// Tool nose radius compensation's tool (G41/G42 on a lathe): the nose
/// radius of the offset in force (geometry, plus the wear while a wear
/// offset is selected) and the imaginary tip from the nose centre, by the
/// tip direction (1-8, X up and Z right; 0 and 9: the centre is
/// programmed).
struct NoseTool {
  Counts radius = 0;
  AxisCounts tip{};
};

NoseTool noseTool(const mbrt_ctx& ctx);

/// G10 P X Y Z R Q (P n: wear, 10000 + n: geometry) or with U V W C, which
/// add to the offset.
mbrt_status writeLatheOffsets(mbrt_ctx& ctx, const FrameWords& words);

} // namespace mbc::rt
