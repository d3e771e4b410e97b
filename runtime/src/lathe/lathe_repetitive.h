// A lathe's multiple repetitive cycles without a shape program (group 00):
// G74 end face peck drilling, G75 outer/inner diameter grooving and G76
// multiple threading (system A and B; C: G76-G78), in the two-block format:
// a first block gives the settings that stay (G74/G75 R the return; G76 P
// finishing passes, chamfer and tool angle, Q the least depth, R the
// finishing allowance), a block with X(U) or Z(W) cuts.
#pragma once

#include "motion_words.h"

namespace mbc::rt {

/// `code`: kLatheOwnCode + 740, 750 or 760 (lathe_codes.h).
mbrt_status executeRepetitiveCycle(mbrt_ctx& ctx, int code,
                                   const CycleWords& words);

} // namespace mbc::rt
