// Canned cycles of the M series: G73 and G83 peck, G74 and G84 tapping, G76
// and G87 fine and back boring, G81/G82 drilling, G85/G86/G88/G89 boring.
// Every hole: position in the plane at the current level (rapid), rapid to
// R, the cycle's own moves, then back to the initial level (G98) or R (G99).
// The drilling axis is Z (parameter 5101#0 FXY = 0, FANUC's default).
//
// The T series' drilling cycles (the 0i-TF manual's "Canned cycle for
// drilling"): G83 face drilling, G84 face tapping and G85 face boring
// drill along Z at a position of X and C; G87, G88 and G89 are the side
// ones, along X at a position of Z and C. R is the distance from the
// initial level to R (a radius, signed) whatever G90/G91 say. G83/G87 with
// Q peck: back by parameter 5114 (5101#2 RTR = 0, high-speed peck) or out
// to R and in again to 5114 short (RTR = 1); without Q they drill in one
// feed. Tapping feeds out with the spindle reversed, boring feeds out. In
// G code system A (no G98/G99 of the return) the tool returns to the
// initial level.
#include "canned_cycles.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <cmath>

#include "programmed_moves.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

/// A length parameter in mm as counts of the current input unit.
Counts parameterCounts(const mbrt_ctx& ctx, int number) {
  const double mm = ctx.profile.parameter(number);
  return static_cast<Counts>(roundHalfAway(mm * ctx.countsPerMm()));
}

/// The moves of one hole; `axis` is the drilling axis.
class Hole {
public:
  Hole(mbrt_ctx& ctx, int axis) : ctx_(ctx), axis_(axis) {}

  mbrt_status to(Counts level, bool rapid) {
    AxisCounts target = programPosition(ctx_);
    if (target[axis_] == level) {
      return 0;
    }
    target[axis_] = level;
    return moveStraight(ctx_, target, rapid, ctx_.machine.modal.cycle);
  }

  mbrt_status rapid(Counts level) { return to(level, true); }

  mbrt_status feed(Counts level) { return to(level, false); }

  void dwellAtBottom() { dwell(ctx_, data().p / 1000.0); }

  /// G76/G87: the tool moves off the bore wall by Q (away = 1) or back
  /// (away = -1), in the direction parameter 5101 #4 RD1 and #5 RD2 give:
  /// +, -, along the plane's first or second axis.
  mbrt_status shift(int away) {
    const bool second = ctx_.profile.parameterBit(5101, 5);
    const bool negative = ctx_.profile.parameterBit(5101, 4);
    const int axis = planeAxis(second ? 1 : 0);
    if (axis < 0 || data().q == 0) {
      return 0;
    }
    AxisCounts target = programPosition(ctx_);
    target[axis] += (negative ? -1 : 1) * away * data().q;
    return moveStraight(ctx_, target, true, ctx_.machine.modal.cycle);
  }

  const CycleData& data() const { return ctx_.machine.modal.cycleData; }

  /// M29 given, or 5200#0 G84: G84 and G74 tap rigidly.
  bool rigid() const {
    return ctx_.machine.modal.rigidTapping ||
           ctx_.profile.parameterBit(5200, 0);
  }

  Counts rLevel() const { return data().hasR ? data().r : data().initial; }

  Counts returnLevel() const {
    return ctx_.machine.modal.returnToR ? rLevel() : data().initial;
  }

  /// Which way the hole goes from R to Z: -1 down, 1 up (G87 goes up).
  int down() const { return data().z < rLevel() ? -1 : 1; }

  mbrt_status peck(bool toR, Counts d, bool rapidRetract);
  mbrt_status backBore();
  mbrt_status drill();

private:
  int planeAxis(int index) const {
    return ctx_.axisOf(planeAxes(ctx_.machine.modal.plane).letters[index]);
  }

  mbrt_ctx& ctx_;
  int axis_;
};

/// Cuts Q at a time to Z. Between pecks the tool backs out d (toR false)
/// or out to R and in again to d short of the depth reached (toR); G73 and
/// G83 (d: 5114, 5115) at rapid, peck rigid tapping (M29, G84/G74 with Q;
/// d: 5213, toR by 5200#5 PCP) at the feed, every move being the spindle's.
mbrt_status Hole::peck(bool toR, Counts d, bool rapidRetract) {
  const Counts q = data().q; // > 0: executeCycleBlock checked
  const int dir = down();
  Counts depth = rLevel();
  while (depth != data().z) {
    Counts next = depth + dir * q;
    if ((data().z - next) * dir < 0) {
      next = data().z;
    }
    if (depth != rLevel()) {
      if (toR) {
        if (mbrt_status st = to(rLevel(), rapidRetract)) {
          return st;
        }
      }
      if (mbrt_status st = to(depth - dir * d, rapidRetract)) {
        return st;
      }
    }
    if (mbrt_status st = feed(next)) {
      return st;
    }
    depth = next;
  }
  return 0;
}

/// G87: shift, rapid to R below the hole, shift back, feed up to Z, dwell,
/// shift, rapid to the initial level, shift back. Always returns to the
/// initial level.
mbrt_status Hole::backBore() {
  mbrt_status st = 0;
  (st = shift(1)) || (st = rapid(rLevel())) || (st = shift(-1)) ||
      (st = feed(data().z));
  if (st != 0) {
    return st;
  }
  dwellAtBottom();
  (st = shift(1)) || (st = rapid(data().initial)) || (st = shift(-1));
  return st;
}

/// A lathe's drilling cycle as the M series' cycle that moves the same
/// way: G83/G87 without Q drill as G82 (feed, dwell, rapid out), tapping
/// as G84, boring as G89. 0 for G83/G87 with Q, which peck.
int millEquivalent(const mbrt_ctx& ctx, int cycle) {
  switch (cycle) {
    case 83:
    case 87:
      return ctx.machine.modal.cycleData.q > 0 ? 0 : 82;
    case 84:
    case 88:
      return 84;
    default: // 85 89
      return 89;
  }
}

mbrt_status Hole::drill() {
  const bool lathe = ctx_.profile.lathe();
  const int cycle = lathe ? millEquivalent(ctx_, ctx_.machine.modal.cycle)
                          : ctx_.machine.modal.cycle;
  if (cycle == 87) {
    return backBore();
  }
  if (mbrt_status st = rapid(rLevel())) {
    return st;
  }
  mbrt_status st = 0;
  switch (cycle) {
    case 0: // a lathe's G83/G87 with Q
      if ((st = peck(ctx_.profile.parameterBit(5101, 2),
                     parameterCounts(ctx_, 5114), true)) == 0) {
        dwellAtBottom();
      }
      break;
    case 73:
    case 83:
      st = peck(cycle == 83, parameterCounts(ctx_, cycle == 83 ? 5115 : 5114),
                true);
      break;
    case 74: // tapping: feed out with the spindle reversed
    case 84:
      st = rigid() && data().q > 0 ? peck(ctx_.profile.parameterBit(5200, 5),
                                          parameterCounts(ctx_, 5213), false)
                                   : feed(data().z);
      if (st == 0) {
        dwellAtBottom();
        st = feed(rLevel());
      }
      break;
    case 89:
      if ((st = feed(data().z)) == 0) {
        dwellAtBottom();
        st = feed(rLevel());
      }
      break;
    case 85:
      (st = feed(data().z)) || (st = feed(rLevel()));
      break;
    case 76:
      if ((st = feed(data().z)) == 0) {
        dwellAtBottom();
        (st = shift(1)) || (st = rapid(returnLevel())) || (st = shift(-1));
      }
      break;
    default: // 81 82 86 88: feed in, (dwell,) rapid out
      st = feed(data().z);
      if (cycle == 82 || cycle == 88) {
        dwellAtBottom();
      }
      break;
  }
  return st != 0 ? st : rapid(returnLevel());
}

/// Whether the block's word for `axis` is incremental: G91, or a lathe's
/// U, W or H.
bool incrementalWord(const mbrt_ctx& ctx, const MotionWords& words, int axis) {
  return ctx.machine.modal.incremental ||
         (words.incrementalMask >> axis & 1) != 0;
}

/// R, Z, Q, P into the drilling data. In G91 (and always on a lathe) R is
/// measured from the initial level; an incremental Z from R.
void takeDrillingData(mbrt_ctx& ctx, const CycleWords& words, int axis) {
  CycleData& data = ctx.machine.modal.cycleData;
  if (words.motion->hasR) {
    data.hasR = true;
    data.r = ctx.machine.modal.incremental || ctx.profile.lathe()
                 ? data.initial + words.motion->r
                 : words.motion->r;
  }
  if ((words.motion->axisMask >> axis & 1) != 0) {
    const Counts z = words.motion->axis[axis];
    const Counts r = data.hasR ? data.r : data.initial;
    data.hasZ = true;
    data.z = incrementalWord(ctx, *words.motion, axis) ? r + z : z;
  }
  if (words.q) {
    data.q = std::llabs(*words.q);
  }
  if (words.p) {
    data.p = *words.p;
  }
}

/// The axis a cycle drills along: Z, or X for a lathe's side cycles.
char drillingAxis(const mbrt_ctx& ctx, int cycle) {
  return ctx.profile.lathe() && cycle >= 87 ? 'X' : 'Z';
}

} // namespace

void changeCycle(mbrt_ctx& ctx, int cycle) {
  if (cycle == ctx.machine.modal.cycle) {
    return;
  }
  if (cycle == 0) {
    ctx.machine.modal.rigidTapping = false; // G80 ends rigid tapping
    ctx.machine.modal.seriesFifteenTap = 0;
  }
  // From a face cycle to a side one the drilling axis changes: its data
  // and initial level start again.
  if (cycle == 0 || ctx.machine.modal.cycle == 0 ||
      drillingAxis(ctx, cycle) != drillingAxis(ctx, ctx.machine.modal.cycle)) {
    ctx.machine.modal.cycleData = CycleData{};
    const int axis = ctx.axisOf(drillingAxis(ctx, cycle));
    if (cycle != 0 && axis >= 0) {
      ctx.machine.modal.cycleData.initial = programPosition(ctx)[axis];
    }
  }
  ctx.machine.modal.cycle = cycle;
}

mbrt_status executeCycleBlock(mbrt_ctx& ctx, const CycleWords& words) {
  const int cycle = ctx.machine.modal.cycle;
  const char letter = drillingAxis(ctx, cycle);
  const int axis = ctx.axisOf(letter);
  if (axis < 0) {
    return raise(ctx, AlarmId::ImproperNcAddress,
                 fmt::format("G{} drills along {}, which this machine lacks",
                             cycle, letter));
  }
  takeDrillingData(ctx, words, axis);
  const std::uint32_t plane = words.motion->axisMask & ~(1u << axis);
  if (words.motion->axisMask == 0 && !words.motion->hasR) {
    return 0;
  }
  const CycleData& data = ctx.machine.modal.cycleData;
  if (!data.hasZ) {
    return raise(
        ctx, AlarmId::ImproperNcAddress,
        fmt::format("G{} without {} (the hole bottom)", cycle, letter));
  }
  if ((cycle == 73 || cycle == 83) && data.q <= 0 && !ctx.profile.lathe()) {
    return raise(ctx, AlarmId::PeckWithoutQ,
                 fmt::format("G{} needs the depth of each peck, Q > 0", cycle));
  }
  const double repeat = words.k ? roundHalfAway(*words.k) : 1.0;
  if (repeat < 0.0 || repeat > 9999.0) {
    return raise(ctx, AlarmId::ImproperNcAddress,
                 fmt::format("G{} K{}: K must be 0 to 9999", cycle, repeat));
  }
  Hole hole(ctx, axis);
  for (int n = 0; n < static_cast<int>(repeat); ++n) {
    AxisCounts target = programPosition(ctx);
    for (int a = 0; a < ctx.axisCount(); ++a) {
      if ((plane >> a & 1) != 0) {
        target[a] = incrementalWord(ctx, *words.motion, a)
                        ? target[a] + words.motion->axis[a]
                        : words.motion->axis[a];
      }
    }
    if (target != programPosition(ctx)) {
      if (mbrt_status st = moveStraight(ctx, target, true, cycle)) {
        return st;
      }
    }
    if (mbrt_status st = hole.drill()) {
      return st;
    }
  }
  return 0;
}

} // namespace mbc::rt
