// G10 L2/L20/L10-L13. The values follow the block's own rules: a literal
// without decimal point is in least increments (unless 3401#0 DPI).
#include "data_input.h"

#include <mbc/arith.h>
#include <mbc/g_codes.h>

#include <fmt/format.h>

#include "cutter_comp.h"
#include "frames.h"
#include "held_block.h"
#include "machine_unit.h"

namespace mbc::rt {

namespace {

double wordValue(const FrameWords& words, char letter) {
  const mbrt_word* word = words.word(letter);
  return word != nullptr ? numeric(word->value) : 0.0;
}

/// L2 P0 (external), P1-P6 (G54-G59); L20 P1-P300 (G54.1).
mbrt_status setWorkOffset(mbrt_ctx& ctx, const FrameWords& words, int l) {
  const double p = roundHalfAway(wordValue(words, 'P'));
  const double last = l == 2 ? 6.0 : kG541Count;
  if (words.word('P') == nullptr || p < (l == 2 ? 0.0 : 1.0) || p > last) {
    return raise(ctx, AlarmId::IllegalPInG10,
                 fmt::format("G10 L{} P{}: P must be {} to {}", l, p,
                             l == 2 ? 0 : 1, last));
  }
  if (const mbrt_status status = refuseUnderCompensation(
          ctx, fmt::format("G10 L{} (a work offset)", l))) {
    return status;
  }
  const int index = l == 2 ? kExternalOffset + static_cast<int>(p)
                           : kFirstG541Offset + static_cast<int>(p) - 1;
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if ((words.axes->axisMask >> axis & 1) != 0) {
      // G91, or a lathe's U/W in G code system A, adds.
      const bool adds = ctx.machine.modal.incremental ||
                        (words.axes->incrementalMask >> axis & 1) != 0;
      const Counts value = words.axes->axis[axis];
      storeWorkOffset(ctx, index, axis,
                      adds ? workOffsetInForce(ctx, index, axis) + value
                           : value);
    }
  }
  resyncProgram(ctx); // the machine stays
  return 0;
}

/// L10 H geometry, L11 H wear, L12 D geometry, L13 D wear; P the number.
mbrt_status setToolOffset(mbrt_ctx& ctx, const FrameWords& words, int l) {
  const double p = roundHalfAway(wordValue(words, 'P'));
  if (words.word('P') == nullptr || p < 1.0 ||
      p > ctx.profile.toolOffsetCount) {
    return raise(ctx, AlarmId::IllegalPInG10,
                 fmt::format("G10 L{} P{}: P must be 1 to {}", l, p,
                             ctx.profile.toolOffsetCount));
  }
  if (!words.axes->hasR) {
    return 0;
  }
  static constexpr double ToolOffset::*kFields[] = {
      &ToolOffset::hGeometry, &ToolOffset::hWear, &ToolOffset::dGeometry,
      &ToolOffset::dWear};
  double& field =
      ctx.data.toolOffsets[static_cast<std::size_t>(p)].*kFields[l - 10];
  const double value = countsToUnits(words.axes->r, ctx.scale());
  field = ctx.machine.modal.incremental ? field + value : value;
  return 0;
}

} // namespace

mbrt_status programmableDataInput(mbrt_ctx& ctx, const FrameWords& words) {
  const mbrt_word* lWord = words.word('L');
  const double l = lWord != nullptr ? roundHalfAway(numeric(lWord->value)) : 0;
  if (l < 0.0 || l > 99.0 || dataInputKind(static_cast<int>(l)) == nullptr) {
    return raise(ctx, AlarmId::Unsupported,
                 lWord != nullptr ? fmt::format("G10 L{}", l)
                                  : std::string("G10 without L"));
  }
  if (l == 2.0 || l == 20.0) {
    return setWorkOffset(ctx, words, static_cast<int>(l));
  }
  return setToolOffset(ctx, words, static_cast<int>(l)); // L10-L13
}

} // namespace mbc::rt

const char* mbc::dataInputKind(int l) {
  switch (l) {
    case 2:  // external, G54-G59
    case 20: // G54.1
      return "a work offset";
    case 10: // H geometry
    case 11: // H wear
    case 12: // D geometry
    case 13: // D wear
      return "a tool offset";
    case 50: // parameter_input.h
    case 52:
      return "the parameters that follow";
    default:
      return nullptr;
  }
}
