// G74, G75 and G76 (lathe_repetitive.h). Lengths are counts in the
// workpiece frame, X as a radius. Words without a decimal point (P, Q) are
// least increments, as the control reads them.
//
// G74 / G75: from the start point A, columns from A towards the end point
// B, Δi (P) apart across the peck axis (G74: X, G75: Z); in each column the
// tool pecks along the other axis Δk (Q) at a time, backing out e after each
// peck, is relieved Δd (R) at the bottom against the column direction and
// returns at rapid; at the end it returns to A.
//
// G76: passes at depths Δd √n (at least Δdmin deeper each time) down to the
// thread height k less the finishing allowance d, then m passes at k. Each
// pass rapids to its depth at the start shifted along the flank (depth ×
// tan(a / 2), towards the thread's end: one edge cuts), threads to the end
// point's Z (with a pull-out over r × 0.1 lead when r > 0, rising at the
// angle of parameter 5131 from Z, 45 degrees when 0),
// rapids out in X and back to A.
//
// In the Series 10/11 tape format (parameter 0001#1 FCV) each is one block:
// G74/G75 give I, K and D for P, Q and R, and take e from parameter 5139;
// G76 gives I, K, D and A.
#include "lathe_repetitive.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "cutter_comp.h"
#include "lathe_codes.h"
#include "lathe_cycles.h"
#include "lathe_settings.h"
#include "lathe_state.h"
#include "programmed_moves.h"

namespace mbc::rt {

namespace {

constexpr int kG74 = kLatheOwnCode + 740;
constexpr int kG76 = kLatheOwnCode + 760;

/// PS0062 with the cycle and what is wrong.
mbrt_status illegal(mbrt_ctx& ctx, int code, std::string_view what) {
  return raise(ctx, AlarmId::IllegalRepetitiveCycle,
               fmt::format("G{}: {}",
                           writtenLatheCode(ctx.profile.gCodeSystem, code),
                           what));
}

Counts towards(Counts from, Counts to, Counts step) {
  return from + (to >= from ? step : -step);
}

/// I (index 0) or K (2) of a Series 10/11 block, in counts; 0 without.
Counts centerWord(const MotionWords& motion, int index) {
  return (motion.centerMask >> index & 1) != 0
             ? motion.center[static_cast<std::size_t>(index)]
             : Counts{0};
}

/// G74 (pecks along Z, columns in X) and G75 (pecks along X, columns in Z).
mbrt_status grooveCycle(mbrt_ctx& ctx, int code, const CycleWords& words) {
  const MotionWords& motion = *words.motion;
  const bool oneBlock = seriesTenFormat(ctx);
  if (motion.axisMask == 0) { // the first block: R is the return e
    if (oneBlock) {
      return illegal(ctx, code,
                     "in the Series 10/11 format (parameter 0001#1 FCV) it "
                     "is one block: X(U) Z(W) I K D F");
    }
    if (motion.hasR) {
      keepCycleLength(ctx, 5139, motion.r);
    }
    return 0;
  }
  const int peckAxis = ctx.axisOf(code == kG74 ? 'Z' : 'X');
  const int columnAxis = ctx.axisOf(code == kG74 ? 'X' : 'Z');
  const int perIncrement = ctx.countsPerIncrement();
  // The amounts along X (P, or I in the Series 10/11 format) and along Z
  // (Q, or K): G74 shifts X and pecks Z, G75 pecks X and shifts Z. The
  // relief at the bottom is R (D, least increments).
  const Counts p =
      oneBlock ? centerWord(motion, 0)
               : static_cast<Counts>(words.p.value_or(0.0)) * perIncrement;
  const Counts q = oneBlock ? centerWord(motion, 2) : words.q.value_or(0);
  const Counts peck = std::llabs(code == kG74 ? q : p);
  const Counts shift = std::llabs(code == kG74 ? p : q);
  const Counts relief =
      oneBlock      ? std::llabs(incrementCounts(ctx, words.d.value_or(0.0)))
      : motion.hasR ? std::llabs(motion.r)
                    : 0;
  const Counts back = cycleLength(ctx, 5139);
  const AxisCounts start = ctx.machine.program;
  const AxisCounts end = cycleEndPoint(ctx, motion);
  if (peck == 0 && end[peckAxis] != start[peckAxis]) {
    return illegal(ctx, code, "the peck depth is 0");
  }
  if (shift == 0 && end[columnAxis] != start[columnAxis]) {
    return illegal(ctx, code, "the shift between cuts is 0");
  }
  const Counts depth = end[peckAxis];
  const Counts columnEnd = end[columnAxis];
  const int label =
      static_cast<int>(writtenLatheCode(ctx.profile.gCodeSystem, code));
  const auto move = [&](const AxisCounts& to, bool rapid) {
    return moveStraight(ctx, to, rapid, label);
  };
  AxisCounts at = start;
  for (bool last = false; !last;) {
    last = at[columnAxis] == columnEnd;
    // Peck down the column.
    const Counts top = start[peckAxis];
    Counts reached = top;
    while (reached != depth) {
      const Counts next = std::abs(depth - reached) <= peck
                              ? depth
                              : towards(reached, depth, peck);
      at[peckAxis] = next;
      if (const mbrt_status status = move(at, false)) {
        return status;
      }
      reached = next;
      if (reached != depth && back > 0) {
        at[peckAxis] = towards(reached, top, back);
        if (const mbrt_status status = move(at, true)) {
          return status;
        }
      }
    }
    // Relieve against the column direction, return to the top.
    const Counts column = at[columnAxis];
    if (relief > 0) {
      at[columnAxis] = columnEnd != start[columnAxis]
                           ? towards(column, start[columnAxis], relief)
                           : column - relief;
      if (const mbrt_status status = move(at, true)) {
        return status;
      }
    }
    at[peckAxis] = top;
    if (const mbrt_status status = move(at, true)) {
      return status;
    }
    at[columnAxis] = last || std::abs(columnEnd - column) <= shift
                         ? columnEnd
                         : towards(column, columnEnd, shift);
    if (!last) {
      if (const mbrt_status status = move(at, true)) {
        return status;
      }
    }
  }
  return at == start ? 0 : move(start, true);
}

/// G76's pass depths (from the crest), increasing to k.
std::vector<Counts> threadDepths(Counts first, Counts least, Counts height,
                                 Counts allowance, int finishing) {
  std::vector<Counts> depths;
  const Counts rough = height - allowance;
  Counts depth = 0;
  for (int n = 1; depth < rough; ++n) {
    Counts next = static_cast<Counts>(
        roundHalfAway(static_cast<double>(first) * std::sqrt(n)));
    next = std::max(next, depth + std::max<Counts>(least, 1));
    depth = std::min(next, rough);
    depths.push_back(depth);
  }
  depths.insert(depths.end(), finishing, height);
  return depths;
}

/// What a G76 block that cuts gives: in counts, the thread height k, the
/// first depth Δd and the taper i; the tool angle in degrees.
struct ThreadWords {
  Counts height = 0;
  Counts first = 0;
  Counts taper = 0;
  double angle = 0.0;
};

mbrt_status cutThread(mbrt_ctx& ctx, const MotionWords& motion,
                      const ThreadWords& thread);

/// G76 in the Series 10/11 format, one block: X(U) Z(W) I(taper)
/// K(height) D(first depth, increments) F(lead) A(tool angle) P(infeed
/// method); the least depth, finishing allowance and passes and the
/// chamfer are parameters 5140, 5141, 5142 and 5130.
mbrt_status seriesTenThreadCycle(mbrt_ctx& ctx, const CycleWords& words) {
  const MotionWords& motion = *words.motion;
  if (motion.axisMask == 0) {
    return illegal(ctx, kG76,
                   "in the Series 10/11 format (parameter 0001#1 FCV) G76 "
                   "is one block: X(U) Z(W) I K D F A P");
  }
  if (words.p && *words.p != 1.0) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("G76 P{}: infeed method {} of the Series 10/11 "
                             "format (mbc cuts P1, one edge with a constant "
                             "cutting amount)",
                             *words.p, *words.p));
  }
  ThreadWords thread;
  thread.taper = centerWord(motion, 0);
  thread.height = centerWord(motion, 2);
  thread.first = incrementCounts(ctx, words.d.value_or(0.0));
  thread.angle = words.a.value_or(cycleSetting(ctx, 5143));
  return cutThread(ctx, motion, thread);
}

mbrt_status threadCycle(mbrt_ctx& ctx, const CycleWords& words) {
  if (seriesTenFormat(ctx)) {
    return seriesTenThreadCycle(ctx, words);
  }
  const MotionWords& motion = *words.motion;
  const int perIncrement = ctx.countsPerIncrement();
  if (motion.axisMask == 0) { // the first block: P(m)(r)(a) Q(Δdmin) R(d)
    if (words.p) {
      const auto p = static_cast<long>(*words.p);
      const double tenths = static_cast<double>(p / 100 % 100);
      const double angle = static_cast<double>(p % 100);
      ctx.lathe->cycleSettings[5142] = static_cast<double>(p / 10000);
      ctx.lathe->cycleSettings[5130] = tenths;
      ctx.lathe->cycleSettings[5143] = angle;
    }
    if (words.q) {
      keepCycleLength(ctx, 5140, *words.q);
    }
    if (motion.hasR) {
      keepCycleLength(ctx, 5141, motion.r);
    }
    return 0;
  }
  ThreadWords thread;
  thread.height = static_cast<Counts>(words.p.value_or(0.0)) * perIncrement;
  thread.first = words.q.value_or(0);
  thread.taper = motion.hasR ? motion.r : 0;
  thread.angle = cycleSetting(ctx, 5143);
  return cutThread(ctx, motion, thread);
}

mbrt_status cutThread(mbrt_ctx& ctx, const MotionWords& motion,
                      const ThreadWords& thread) {
  const int x = ctx.axisOf('X');
  const int z = ctx.axisOf('Z');
  const Counts height = thread.height;
  const Counts first = thread.first;
  const double lead = ctx.machine.modal.feed;
  if (height <= 0 || first <= 0) {
    return illegal(ctx, kG76,
                   seriesTenFormat(ctx)
                       ? "the thread height K and first depth D must be "
                         "greater than 0"
                       : "the thread height P and first depth Q must be "
                         "greater than 0");
  }
  const int finishing = static_cast<int>(cycleSetting(ctx, 5142));
  const double angle = thread.angle;
  const Counts least = cycleLength(ctx, 5140);
  const Counts allowance = cycleLength(ctx, 5141);
  if (allowance >= height) {
    return illegal(ctx, kG76,
                   "the finishing allowance is not less than the "
                   "thread height");
  }
  const AxisCounts start = ctx.machine.program;
  const AxisCounts end = cycleEndPoint(ctx, motion);
  const Counts taper = thread.taper;
  // The crest lies towards A: an outer thread is cut inwards.
  const Counts outward = start[x] >= end[x] ? 1 : -1;
  const Counts forward = end[z] >= start[z] ? 1 : -1;
  const double flank = std::tan(angle / 2.0 * std::numbers::pi / 180.0);
  const Counts chamfer = static_cast<Counts>(
      roundHalfAway(cycleSetting(ctx, 5130) * 0.1 * lead * ctx.scale()));
  // The pull-out rises at 5131's angle from Z (0: 45 degrees).
  const double pullAngle =
      cycleSetting(ctx, 5131) > 0.0 ? cycleSetting(ctx, 5131) : 45.0;
  const auto rise = static_cast<Counts>(
      roundHalfAway(static_cast<double>(chamfer) *
                    std::tan(pullAngle * std::numbers::pi / 180.0)));
  const int label =
      static_cast<int>(writtenLatheCode(ctx.profile.gCodeSystem, kG76));
  const auto move = [&](Counts px, Counts pz, bool rapid) {
    AxisCounts to = ctx.machine.program;
    to[x] = px;
    to[z] = pz;
    return moveStraight(ctx, to, rapid, label);
  };
  const auto pass = [&](Counts depth) {
    const Counts atDepth = end[x] + outward * (height - depth);
    const auto shift =
        static_cast<Counts>(roundHalfAway(static_cast<double>(depth) * flank)) *
        forward;
    const Counts threadEnd = end[z] - forward * chamfer;
    mbrt_status status = move(atDepth + taper, start[z] + shift, true);
    if (status == 0) {
      status = move(atDepth, threadEnd, false);
    }
    if (status == 0 && chamfer > 0) {
      status = move(atDepth + outward * rise, end[z], false);
    }
    if (status == 0) {
      status = move(start[x], ctx.machine.program[z], true);
    }
    return status != 0 ? status : move(start[x], start[z], true);
  };
  // The feed moves thread: F is the lead, whatever G98/G99.
  const int motionMode = ctx.machine.modal.motion;
  ctx.machine.modal.motion = kThreadingMotion;
  mbrt_status status = 0;
  for (const Counts depth :
       threadDepths(first, least, height, allowance, finishing)) {
    if ((status = pass(depth)) != 0) {
      break;
    }
  }
  ctx.machine.modal.motion = motionMode;
  return status;
}

} // namespace

mbrt_status executeRepetitiveCycle(mbrt_ctx& ctx, int code,
                                   const CycleWords& words) {
  // G74-G76 cut uncompensated, from a start point without the offset
  // vector of tool nose radius compensation (cutter_comp.h).
  if (words.motion->axisMask != 0) {
    if (const mbrt_status status = cancelVectorHere(ctx)) {
      return status;
    }
  }
  return code == kG76 ? threadCycle(ctx, words) : grooveCycle(ctx, code, words);
}

} // namespace mbc::rt
