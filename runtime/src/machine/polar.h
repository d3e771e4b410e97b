// The polar coordinate command (G16): in the plane of G17/G18/G19 the
// first axis word is a radius and the second an angle in degrees,
// counter-clockwise from the first axis (docs/language.md, "Polar
// coordinates").
#pragma once

#include "motion_words.h"

namespace mbc::rt {

/// Turns the plane words of a block that moves in G16 (a radius, an angle
/// or both) into the Cartesian words G90 or G91 reads, in program
/// coordinates (before G68 rotation, scaling and mirror). The pole is the
/// program's zero (the G52 local origin) unless a G91 radius is written,
/// which measures from the current position. A word left out keeps the
/// current position's radius or angle about the program's zero; a G91
/// angle adds to the current position's angle. Other axes stay as written.
void polarToCartesian(const mbrt_ctx& ctx, MotionWords& words);

/// Whether the block writes a word of the current plane.
bool writesPlaneWords(const mbrt_ctx& ctx, const MotionWords& words);

} // namespace mbc::rt
