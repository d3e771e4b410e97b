// bench/workloads/pocket.nc by hand: a zig-zag pocket in 80 layers.
#include "hand_run.h"

int main() {
  using mbc::bench::w;
  mbc::bench::HandRun run;
  run.block({w('G', 90), w('G', 17), w('G', 21), w('G', 54), w('G', 0),
             w('X', 0), w('Y', 0), w('Z', 5)});
  for (int layer = 1; layer <= 80; ++layer) {
    run.block({w('G', 0), w('X', 0), w('Y', 0)});
    run.block({w('G', 1), w('Z', -layer * 0.125), w('F', 300)});
    bool atEnd = false;
    // The macro steps Y by adding 0.1 up to 80: the same sums here.
    for (double y = 0; y <= 80.0; y += 0.1) {
      run.block({w('G', 1), w('Y', y), w('F', 1200)});
      run.block({w('G', 1), w('X', atEnd ? 0.0 : 120.0)});
      atEnd = !atEnd;
    }
    run.block({w('G', 0), w('Z', 5)});
  }
}
