// bench/workloads/helix.nc by hand: thread milling a 60 x 60 grid.
#include <cmath>
#include <numbers>

#include "hand_run.h"

int main() {
  using mbc::bench::w;
  mbc::bench::HandRun run;
  const double degrees = std::numbers::pi / 180.0;
  const double radius = 3.75;
  run.block(
      {w('G', 90), w('G', 17), w('G', 21), w('G', 54), w('G', 0), w('Z', 5)});
  for (int hole = 0; hole < 60 * 60; ++hole) {
    const double x = (hole % 60) * 25.0;
    const double y = (hole / 60) * 25.0;
    run.block({w('G', 0), w('X', x + radius), w('Y', y)});
    run.block({w('G', 1), w('Z', -18), w('F', 800)});
    for (int quarter = 0; quarter < 48; ++quarter) {
      const int next = quarter + 1;
      run.block({w('G', 3), w('X', x + radius * std::cos(next * 90 * degrees)),
                 w('Y', y + radius * std::sin(next * 90 * degrees)),
                 w('Z', -18 + 1.5 * next / 4),
                 w('I', -radius * std::cos(quarter * 90 * degrees)),
                 w('J', -radius * std::sin(quarter * 90 * degrees))});
    }
    run.block({w('G', 1), w('X', x), w('Y', y)});
    run.block({w('G', 0), w('Z', 5)});
  }
}
