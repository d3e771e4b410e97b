// Chamfering and corner R of a lathe (lathe_corners.h).
#include "lathe_corners.h"

#include <fmt/format.h>

#include <cstdlib>

#include "corner_blends.h"
#include "corner_state.h"
#include "cutter_comp_state.h"
#include "programmed_moves.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

int signOf(Counts value) {
  return value < 0 ? -1 : 1;
}

/// The I, J or K letter that gives the chamfer into `axis` of the plane.
char chamferLetter(const mbrt_ctx& ctx, int axis) {
  const PlaneAxes axes = planeAxes(ctx.machine.modal.plane);
  const int index = axes.centerIndex[axis == planeIndex(ctx).p ? 0 : 1];
  return static_cast<char>('I' + index);
}

bool hasCenterWord(const MotionWords& words, char letter) {
  return (words.centerMask >> (letter - 'I') & 1) != 0;
}

/// Whether `to` differs from `from` on an axis other than `axis`.
bool movesBesides(const mbrt_ctx& ctx, const AxisCounts& from,
                  const AxisCounts& to, int axis) {
  for (int other = 0; other < ctx.axisCount(); ++other) {
    if (other != axis && from[other] != to[other]) {
      return true;
    }
  }
  return false;
}

std::string letterOf(const mbrt_ctx& ctx, int axis) {
  return std::string(1, ctx.profile.axes[static_cast<std::size_t>(axis)]);
}

} // namespace

bool chamferByC(const mbrt_ctx& ctx) {
  return ctx.profile.lathe() && ctx.profile.parameterBit(3405, 4) &&
         ctx.axisOf('C') < 0;
}

bool angleByA(const mbrt_ctx& ctx) {
  return ctx.profile.lathe() && ctx.profile.parameterBit(3405, 4) &&
         ctx.axisOf('A') < 0;
}

bool insertsCorner(const mbrt_ctx& ctx, const MotionWords& words) {
  if (ctx.compensation->codeInBlock) {
    return false; // G41/G42 I K: the direction of the start-up (mill)
  }
  const PlaneAxes axes = planeAxes(ctx.machine.modal.plane);
  const std::uint32_t planeCenters = (std::uint32_t{1} << axes.centerIndex[0]) |
                                     (std::uint32_t{1} << axes.centerIndex[1]);
  const bool chamferWord =
      chamferByC(ctx) ? words.hasC : (words.centerMask & planeCenters) != 0;
  return words.hasR || chamferWord;
}

mbrt_status holdCornerMove(mbrt_ctx& ctx, const MotionWords& words,
                           const AxisCounts& start, const AxisCounts& target) {
  const PlaneIndex plane = planeIndex(ctx);
  if (plane.p < 0 || plane.q < 0) {
    return missingPlaneAxis(ctx);
  }
  const bool alongP = target[plane.p] != start[plane.p];
  const int along = alongP ? plane.p : plane.q;
  const int toward = alongP ? plane.q : plane.p;
  if (target[along] == start[along] ||
      movesBesides(ctx, start, target, along)) {
    return raise(ctx, AlarmId::TaperInCorner,
                 fmt::format("a G01 with a chamfer or corner R moves along "
                             "one axis only ({} or {})",
                             letterOf(ctx, plane.p), letterOf(ctx, plane.q)));
  }
  const bool byC = chamferByC(ctx);
  const char intoToward = chamferLetter(ctx, toward);
  const char intoAlong = chamferLetter(ctx, along);
  if (!byC && hasCenterWord(words, intoAlong)) {
    return raise(ctx, AlarmId::TaperInCorner,
                 fmt::format("{} chamfers into {}, but this G01 moves along "
                             "{}: the chamfer into {} is {}",
                             intoAlong, letterOf(ctx, along),
                             letterOf(ctx, along), letterOf(ctx, toward),
                             intoToward));
  }
  const bool chamfer = byC ? words.hasC : hasCenterWord(words, intoToward);
  if (chamfer && words.hasR) {
    return raise(ctx, AlarmId::TooManyAddressCommands,
                 fmt::format("{} and R in one block: a chamfer or a corner R",
                             byC ? 'C' : intoToward));
  }
  const Counts amount =
      words.hasR ? words.r
      : byC      ? words.c
                 : words.center[static_cast<std::size_t>(intoToward - 'I')];
  if (amount == 0) {
    return moveLine(ctx, target, false);
  }
  if (std::abs(target[along] - start[along]) < std::abs(amount)) {
    return raise(
        ctx, AlarmId::MissingCornerMove,
        fmt::format("the move along {} is shorter than the {} of "
                    "{}",
                    letterOf(ctx, along), words.hasR ? "corner R" : "chamfer",
                    static_cast<double>(std::abs(amount)) / ctx.scale()));
  }
  CornerInsertion& held = *ctx.corner;
  held = CornerInsertion{true,
                         true,
                         words.hasR,
                         start,
                         target,
                         along,
                         toward,
                         amount,
                         ctx.run.block.file,
                         ctx.run.block.line,
                         captureBlock(ctx)};
  ctx.machine.program = target;
  return 0;
}

mbrt_status moveAfterCorner(mbrt_ctx& ctx, const MotionWords& words,
                            const AxisCounts& target) {
  if (ctx.corner->anyAngle()) {
    return moveAfterBlend(ctx, words, target);
  }
  CornerInsertion held = *ctx.corner;
  ctx.corner->pending = false;
  const std::string toward = letterOf(ctx, held.toward);
  if (ctx.machine.modal.motion != 1) {
    return raise(ctx, AlarmId::NotG01AfterCorner,
                 fmt::format("the block after a chamfer or corner R (line "
                             "{}) must be G01 along {}",
                             held.line, toward));
  }
  const Counts run = target[held.toward] - held.corner[held.toward];
  if (run == 0 || movesBesides(ctx, held.corner, target, held.toward) ||
      signOf(run) != signOf(held.amount)) {
    return raise(ctx, AlarmId::MissingMoveAfterCorner,
                 fmt::format("the block after a chamfer or corner R (line "
                             "{}) must move along {} alone, {}",
                             held.line, toward,
                             held.amount > 0 ? "up (the amount is positive)"
                                             : "down (the amount is "
                                               "negative)"));
  }
  if (std::abs(run) < std::abs(held.amount)) {
    return raise(ctx, AlarmId::MissingCornerMove,
                 fmt::format("the move along {} is shorter than the {} of "
                             "line {}",
                             toward, held.round ? "corner R" : "chamfer",
                             held.line));
  }
  AxisCounts d = held.corner; // the amount short of the corner
  d[held.along] -= signOf(held.corner[held.along] - held.from[held.along]) *
                   std::abs(held.amount);
  AxisCounts c = held.corner; // the amount along the next move
  c[held.toward] += held.amount;
  ctx.machine.program = held.from;
  const mbrt_status status = asHeldBlock(ctx, held, [&] {
    if (const mbrt_status toD = moveLine(ctx, d, false)) {
      return toD;
    }
    if (!held.round) {
      return moveLine(ctx, c, false);
    }
    AxisCounts center = d;
    center[held.toward] += held.amount;
    // Turning from the held move's direction towards the next one's: in
    // the plane's first-second axis order that is counter-clockwise (G03)
    // when the turn is positive.
    const int travel = signOf(held.corner[held.along] - held.from[held.along]);
    const int turn = held.along == planeIndex(ctx).p
                         ? travel * signOf(held.amount)
                         : -travel * signOf(held.amount);
    return moveArcAbout(ctx, c, center, turn < 0);
  });
  if (status != 0) {
    return status;
  }
  // The next move may end with a corner of its own.
  if (words.blend != 0) {
    return holdBlendMove(ctx, words, c, target);
  }
  return insertsCorner(ctx, words) ? holdCornerMove(ctx, words, c, target)
                                   : moveLine(ctx, target, false);
}

mbrt_status checkCornerTaken(mbrt_ctx& ctx) {
  CornerInsertion& held = *ctx.corner;
  if (held.fresh) {
    held.fresh = false;
    return 0;
  }
  held.pending = false;
  if (held.openEnd) {
    return raise(ctx, AlarmId::NoEndPointAndAngle,
                 fmt::format("the ,A line of line {} has no end point: the "
                             "next block gives it",
                             held.line));
  }
  return raise(ctx, AlarmId::MissingMoveAfterCorner,
               fmt::format("the block after a chamfer or corner R (line {}) "
                           "must be a {}",
                           held.line,
                           held.blend != 0
                               ? "G01, G02 or G03 move in the plane"
                               : "G01 along " + letterOf(ctx, held.toward)));
}

void releaseCornerMove(mbrt_ctx& ctx) {
  const CornerInsertion held = *ctx.corner;
  if (!held.pending) {
    return;
  }
  ctx.corner->pending = false;
  if (held.anyAngle()) {
    runHeldAsProgrammed(ctx, held);
    return;
  }
  ctx.machine.program = held.from;
  asHeldBlock(ctx, held, [&] { return moveLine(ctx, held.corner, false); });
}

} // namespace mbc::rt
