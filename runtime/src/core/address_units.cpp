// What one least increment of an address is worth (declared in context.h):
// the block reader, the flattened program, the API and ADP all read words
// by it.
#include <mbc/addresses.h>

#include "context.h"

namespace mbc::rt {

double addressCountsPerUnit(const mbrt_ctx& ctx, char letter) {
  if (letter == 'G') {
    return 10.0;
  }
  if (const int axis = ctx.movedAxisOf(letter); axis >= 0) {
    return ctx.axisIncrements(axis);
  }
  if (isArcCenterLetter(letter) || letter == 'Q' || letter == 'F' ||
      letter == commaWordLetter('C') || letter == commaWordLetter('R')) {
    return ctx.inputScale();
  }
  if (letter == commaWordLetter('A')) {
    return kCountsPerDegree; // 0.001 degree in inches too
  }
  return 1.0;
}

} // namespace mbc::rt
