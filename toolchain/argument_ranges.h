// `mbc check --main O9040 --arg X=0..20 --prove`: the ranges the main
// program's arguments are checked over (alarm_ranges.h does the work).
#pragma once

#include <string>
#include <vector>

namespace mbc::toolchain {

/// One `--arg LETTER=LO..HI` (or `LETTER=V`, LO = HI).
struct ArgumentRange {
  char letter = 'A';
  double lo = 0;
  double hi = 0;
};

struct AlarmRangeRequest {
  std::string mainProgram; // "" for the first program of the input
  std::vector<ArgumentRange> args;
};

} // namespace mbc::toolchain
