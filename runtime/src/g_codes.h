// The G codes of a FANUC 0i-MF (M series) with their names, so that a G code
// mbc does not execute yet is told apart from one FANUC does not have.
#pragma once

#include <mbc/g_codes.h>

namespace mbc::rt {

struct GCodeInfo {
  int tenths;    // G54.1 -> 541
  bool modelled; // mbc executes it; otherwise the run stops with MBC0001
  const char* name;
};

/// The FANUC G code with this number in tenths, or nullptr if there is none.
const GCodeInfo* findGCode(int tenths);

} // namespace mbc::rt
