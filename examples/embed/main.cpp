// Calls a compiled Macro B cycle from C++, as a simulation loop would:
// `mbc compile -c cycle.nc -o cycle.o --header cycle.h` gives the object and
// its header; this program links them with the mbc runtime library. It
// shows a loop of calls in one context, the motion callback, variables in
// and out, an alarm as a status code, the toolpath buffer, and contexts
// running in parallel threads. docs/embedding.md explains each call.
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "cycle.h"

namespace {

struct PathLength {
  double length = 0;
  double x = 0, y = 0, z = 0;
};

void onMotion(void* user, const mbrt_motion* m) {
  auto* path = static_cast<PathLength*>(user);
  double dx = m->end[0] - path->x, dy = m->end[1] - path->y,
         dz = m->end[2] - path->z;
  path->length += std::sqrt(dx * dx + dy * dy + dz * dz);
  path->x = m->end[0];
  path->y = m->end[1];
  path->z = m->end[2];
}

void onAlarm(void*, const char* text, size_t size) {
  std::printf("alarm callback: %.*s", static_cast<int>(size), text);
}

mbrt_ctx* newContext() {
  char err[256];
  mbrt_ctx* ctx = mbrt_create(nullptr, err, sizeof err); // 3-axis mill
  if (ctx == nullptr) {
    std::fprintf(stderr, "cannot create a context: %s\n", err);
  }
  return ctx;
}

// One call of O9100 like `G65 P9100 X0 Y0 R.. H.. Z-5. F150.`.
mbrt_status drill(mbrt_ctx* ctx, double radius, double holes) {
  const mbrt_word args[] = {
      {'X', MBRT_WORD_VALUE, 0.0},    {'Y', MBRT_WORD_VALUE, 0.0},
      {'R', MBRT_WORD_VALUE, radius}, {'H', MBRT_WORD_VALUE, holes},
      {'Z', MBRT_WORD_VALUE, -5.0},   {'F', MBRT_WORD_VALUE, 150.0}};
  return mbc_O9100(ctx, args, holes > 0 ? 6 : 3);
}

double read(mbrt_ctx* ctx, int number) {
  mbrt_num value = 0;
  mbrt_read_var(ctx, number, &value);
  return value;
}

// The same parts in a context of its own: the total path length.
double simulate(double firstRadius) {
  mbrt_ctx* ctx = newContext();
  PathLength path;
  mbrt_set_motion_sink(ctx, onMotion, &path);
  for (int part = 0; part < 50; ++part) {
    drill(ctx, firstRadius + part, 4 + part % 5);
  }
  mbrt_destroy(ctx);
  return path.length;
}

} // namespace

int main() {
  mbrt_ctx* ctx = newContext();
  if (ctx == nullptr) {
    return 1;
  }

  // A loop of calls; commons carry over between calls until mbrt_reset.
  PathLength path;
  mbrt_set_motion_sink(ctx, onMotion, &path);
  for (int holes = 3; holes <= 6; ++holes) {
    mbrt_status st = drill(ctx, 10.0 * holes, holes);
    std::printf("R%-3d H%d: status %d, #100 = %g, #101 = %g, path %.3f mm\n",
                10 * holes, holes, st, read(ctx, 100), read(ctx, 101),
                path.length);
  }
  mbrt_reset(ctx);
  std::printf("after reset: #101 is %s\n",
              std::isnan(read(ctx, 101)) ? "vacant" : "set");

  // An alarm is a status code; the report says where it happened.
  mbrt_set_alarm_sink(ctx, onAlarm, nullptr);
  mbrt_status st = drill(ctx, 10.0, 0); // no H argument: #3000 = 1
  char report[512];
  mbrt_alarm_report(ctx, report, sizeof report);
  std::printf("status %d, report: %s", st, report);

  // The toolpath buffer instead of a callback.
  mbrt_buffer_motions(ctx, 1);
  drill(ctx, 25.0, 4);
  size_t count = 0;
  const mbrt_motion* motions = mbrt_buffered_motions(ctx, &count);
  std::printf("buffered %zu motions; hole 2 at X%.3f Y%.3f (%s line %d)\n",
              count, motions[3].end[0], motions[3].end[1], motions[3].program,
              motions[3].line);
  mbrt_destroy(ctx);

  // Independent contexts run compiled cycles in parallel threads.
  std::vector<double> lengths(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&lengths, t] { lengths[t] = simulate(5.0 + t); });
  }
  for (std::thread& t : threads) {
    t.join();
  }
  for (int t = 0; t < 4; ++t) {
    bool same = std::fabs(lengths[t] - simulate(5.0 + t)) == 0.0;
    std::printf("thread %d: path %.3f mm (%s)\n", t, lengths[t],
                same ? "same as alone" : "DIFFERENT");
  }
  return 0;
}
