// A lathe's tool offset variables (T series, geometry and wear memory):
// per offset n, X wear #2000+n / #10000+n, Z wear #2100+n / #11000+n, nose
// radius wear #2200+n / #12000+n, tip direction #2300+n / #13000+n, Y wear
// #2400+n / #14000+n, X geometry #2700+n / #15000+n, Z geometry #2800+n /
// #16000+n, nose radius geometry #2900+n / #17000+n, Y geometry #2450+n /
// #19000+n. The short forms reach offset 64 (Y: 49).
#pragma once

#include <vector>

#include "context.h"

namespace mbc::rt {

/// Whether #n lies where a lathe numbers its offsets (#2001-#2999,
/// #10001-#19999): a lathe reads those here, a number there that is no
/// offset of the machine being PS0115.
inline bool isLatheOffsetNumber(long n) {
  return (n >= 2001 && n <= 2999) || (n >= 10001 && n <= 19999);
}

/// One series of a lathe's offset variables: #shortBase+n up to the short
/// count, #longBase+n up to 999, and the profile's name of the field.
struct LatheOffsetVariables {
  int shortBase;
  int shortCount;
  int longBase;
  const char* key;
};

/// Every series (docs/control-tables.md).
std::vector<LatheOffsetVariables> latheOffsetVariables();

mbrt_status readLatheOffset(mbrt_ctx& ctx, long n, Num* out);

/// Writes the offset memory: a T code takes the new value the next time it
/// selects the offset.
mbrt_status writeLatheOffset(mbrt_ctx& ctx, long n, Num value);

} // namespace mbc::rt
