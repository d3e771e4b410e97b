// A simulation loop around a compiled cycle: O9200 (pocket.nc, a circular
// pocket) is called for many parameter sets, as a digital twin or a
// design-of-experiments sweep would, and its motions are consumed through
// the motion callback: path lengths (arcs by their true length) and the
// cutting time at the programmed feed. It prints the totals, which
// sim_loop.py computes the same way through ctypes, and the throughput.
//
//   sim_loop [CALLS]      (default 20000)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "pocket.h"

namespace {

struct Totals {
  long long calls = 0, alarms = 0, motions = 0, circles = 0;
  double feedLength = 0, rapidLength = 0, cuttingMinutes = 0;
};

double distance(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) +
                   (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The length of an XY arc (the cycle works in G17) with its helix rise: a
// full circle when it ends where it began.
double arcLength(const mbrt_motion& m) {
  const double kPi = 3.14159265358979323846;
  const double sx = m.start[0] - m.center[0], sy = m.start[1] - m.center[1];
  const double ex = m.end[0] - m.center[0], ey = m.end[1] - m.center[1];
  double sweep = std::atan2(ey, ex) - std::atan2(sy, sx);
  if (m.kind == MBRT_MOTION_CCW) {
    sweep = sweep <= 0 ? sweep + 2 * kPi : sweep;
  } else {
    sweep = sweep >= 0 ? sweep - 2 * kPi : sweep;
  }
  const double planar = std::fabs(sweep) * std::hypot(sx, sy);
  return std::hypot(planar, m.end[2] - m.start[2]);
}

void onMotion(void* user, const mbrt_motion* m) {
  auto* t = static_cast<Totals*>(user);
  ++t->motions;
  if (m->kind == MBRT_MOTION_RAPID) {
    t->rapidLength += distance(m->start, m->end);
    return;
  }
  const double length = m->kind == MBRT_MOTION_LINEAR
                            ? distance(m->start, m->end)
                            : arcLength(*m);
  t->feedLength += length;
  t->cuttingMinutes += length / m->feed;
}

// Parameter set i: pockets of 10 to 29.5 mm radius, 2 to 8 mm deep, with
// 6, 8 or 10 mm tools; every 1000th asks for a 40 mm tool in a 10 mm
// pocket, which the cycle refuses with alarm 3004.
mbrt_status pocket(mbrt_ctx* ctx, long long i) {
  const double radius =
      (i % 1000 == 999) ? 10.0 : 10.0 + static_cast<double>(i % 40) * 0.5;
  const double tool =
      (i % 1000 == 999) ? 40.0 : 6.0 + static_cast<double>(i % 3) * 2.0;
  const mbrt_word args[] = {
      {'X', MBRT_WORD_VALUE, static_cast<double>(i % 5) * 100.0},
      {'Y', MBRT_WORD_VALUE, 0.0},
      {'Z', MBRT_WORD_VALUE, -2.0 - static_cast<double>(i % 7)},
      {'R', MBRT_WORD_VALUE, radius},
      {'D', MBRT_WORD_VALUE, tool},
      {'Q', MBRT_WORD_VALUE, 1.5},
      {'F', MBRT_WORD_VALUE, 300.0 + static_cast<double>(i % 4) * 100.0}};
  return mbc_O9200(ctx, args, sizeof args / sizeof args[0]);
}

} // namespace

int main(int argc, char** argv) {
  const long long calls = argc > 1 ? std::atoll(argv[1]) : 20000;
  char err[256];
  mbrt_ctx* ctx = mbrt_create(nullptr, err, sizeof err);
  if (ctx == nullptr) {
    std::fprintf(stderr, "sim-loop: cannot create a context: %s\n", err);
    return 1;
  }
  Totals t;
  mbrt_set_motion_sink(ctx, onMotion, &t);
  const auto start = std::chrono::steady_clock::now();
  for (long long i = 0; i < calls; ++i) {
    if (pocket(ctx, i) != 0) {
      if (++t.alarms == 1) {
        char report[512];
        mbrt_alarm_report(ctx, report, sizeof report);
        std::printf("sim-loop: call %lld: %s", i, report);
      }
      continue;
    }
    mbrt_num circles = 0;
    mbrt_read_var(ctx, 100, &circles);
    t.circles += static_cast<long long>(circles);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  mbrt_destroy(ctx);
  std::printf("sim-loop: %lld calls, %lld alarms, %lld motions, %lld "
              "circles\n",
              calls, t.alarms, t.motions, t.circles);
  std::printf("sim-loop: feed path %.3f mm, rapid path %.3f mm, cutting time "
              "%.3f min\n",
              t.feedLength, t.rapidLength, t.cuttingMinutes);
  std::printf("throughput: %.0f calls/s, %.2f M motions/s\n",
              static_cast<double>(calls) / seconds,
              static_cast<double>(t.motions) / seconds / 1e6);
  return 0;
}
