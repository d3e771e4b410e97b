// How the profile's G code system writes a code of the G code table, for
// the lathe's alarms and labels.
#include "lathe_codes.h"

namespace mbc::rt {

double writtenLatheCode(const mbrt_ctx& ctx, int code) {
  const int tenths = columnTenths(ctx.profile.gCodeSystem, code);
  return tenths != kNo ? tenths / 10.0 : 0.0;
}

} // namespace mbc::rt
