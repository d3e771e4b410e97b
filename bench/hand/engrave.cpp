// bench/workloads/engrave.nc by hand: serial numbers in seven segments.
#include "hand_run.h"

namespace {

constexpr int kDigits[10] = {63, 6, 91, 79, 102, 109, 125, 7, 127, 111};
constexpr double kSegments[7][4] = {{0, 8, 4, 8}, {4, 8, 4, 4}, {4, 4, 4, 0},
                                    {4, 0, 0, 0}, {0, 0, 0, 4}, {0, 4, 0, 8},
                                    {0, 4, 4, 4}};

} // namespace

int main() {
  using mbc::bench::w;
  mbc::bench::HandRun run;
  const double scale = 0.5;
  run.block(
      {w('G', 90), w('G', 17), w('G', 21), w('G', 54), w('G', 0), w('Z', 2)});
  for (int serial = 1; serial <= 4000; ++serial) {
    const double x0 = ((serial - 1) % 50) * 14.0;
    const double y0 = ((serial - 1) / 50) * 8.0;
    int place = 1000;
    for (int digit = 0; digit < 4; ++digit, place /= 10) {
      const int segments = kDigits[serial / place % 10];
      for (int s = 0; s < 7; ++s) {
        if ((segments >> s & 1) == 0) {
          continue;
        }
        const double* e = kSegments[s];
        const double x = x0 + digit * 3;
        run.block(
            {w('G', 0), w('X', x + e[0] * scale), w('Y', y0 + e[1] * scale)});
        run.block({w('G', 1), w('Z', -0.1), w('F', 200)});
        run.block({w('G', 1), w('X', x + e[2] * scale),
                   w('Y', y0 + e[3] * scale), w('F', 600)});
        run.block({w('G', 0), w('Z', 0.5)});
      }
    }
  }
  run.block({w('G', 0), w('Z', 10)});
}
