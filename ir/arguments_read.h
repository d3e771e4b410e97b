// Which of #1-#33 a program reads as they stand when it starts: the G65
// arguments a caller of its entry point gives it a use for (the C header
// lists them). Reads of its M98 subprograms count, as they share its
// locals; a G65 macro it calls has locals of its own.
#pragma once

#include "ir/ir.h"

#include <bitset>

namespace mbc::ir {

struct ArgumentsRead {
  std::bitset<33> locals; // bit n-1: #n
  // It may also read locals by a computed number (#[...], ADP[#[...]]),
  // or it calls a subprogram by a computed P: no list can be sure.
  bool computed = false;
  // The locals it writes (#n = ...), and whether it may write others by a
  // computed number (#[...] = ...): a local read and never written can
  // only be an argument.
  std::bitset<33> written;
  bool computedWrite = false;
};

ArgumentsRead argumentsRead(const Module& module, const Function& f);

} // namespace mbc::ir
