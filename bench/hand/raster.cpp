// bench/workloads/raster.nc by hand: Z = 4 sin x cos y over 1000 x 1000.
#include <cmath>
#include <numbers>

#include "hand_run.h"

int main() {
  using mbc::bench::w;
  mbc::bench::HandRun run;
  const double degrees = std::numbers::pi / 180.0;
  run.block({w('G', 90), w('G', 17), w('G', 21), w('G', 54), w('G', 0),
             w('X', 0), w('Y', 0), w('Z', 10)});
  run.block({w('G', 1), w('F', 2000)});
  for (int row = 0; row < 1000; ++row) {
    const double y = row * 0.1;
    const double amplitude = std::cos(y * 12 * degrees) * 4;
    for (int column = 0; column < 1000; ++column) {
      const double x = column * 0.1;
      run.block({w('X', x), w('Y', y),
                 w('Z', std::sin(x * 12 * degrees) * amplitude)});
    }
  }
  run.block({w('G', 0), w('Z', 10)});
}
