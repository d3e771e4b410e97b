// The access classes of variable numbers on the default machine (spec §2.1,
// §6): which numbers exist and which are read-only or write-only.
#include <mbc/sysvars.h>

namespace mbc {

namespace {

struct Range {
  int first;
  int last;
  VarAccess access;
};

constexpr Range kRanges[] = {
    {0, 0, VarAccess::ReadOnly},          // vacant
    {1, 33, VarAccess::ReadWrite},        // locals
    {100, 199, VarAccess::ReadWrite},     // common, volatile
    {500, 999, VarAccess::ReadWrite},     // common, nonvolatile
    {1000, 1015, VarAccess::ReadOnly},    // UI000-UI015
    {1032, 1032, VarAccess::ReadOnly},    // UI as a word
    {1100, 1115, VarAccess::ReadWrite},   // UO000-UO015
    {1132, 1133, VarAccess::ReadWrite},   // UO as words
    {2001, 2400, VarAccess::ReadWrite},   // H wear / geometry (memory C)
    {3000, 3000, VarAccess::WriteOnly},   // macro alarm
    {3001, 3005, VarAccess::ReadWrite},   // clocks, #3003-#3005
    {3006, 3006, VarAccess::WriteOnly},   // stop with message
    {3007, 3007, VarAccess::ReadOnly},    // mirror image
    {3011, 3012, VarAccess::ReadOnly},    // date, time
    {3901, 3902, VarAccess::ReadWrite},   // parts
    {4000, 4030, VarAccess::ReadOnly},    // main program, modal groups
    {4101, 4130, VarAccess::ReadOnly},    // last-value words
    {4201, 4230, VarAccess::ReadOnly},    // modal, executing block
    {4301, 4330, VarAccess::ReadOnly},    // words, executing block
    {5001, 5120, VarAccess::ReadOnly},    // positions
    {5201, 5340, VarAccess::ReadWrite},   // EXT and G54-G59 offsets
    {7001, 7960, VarAccess::ReadWrite},   // G54.1 P1-P48
    {10001, 13999, VarAccess::ReadWrite}, // tool offsets
    {14001, 19988, VarAccess::ReadWrite}, // G54.1 P1-P300
};

} // namespace

VarAccess variableAccess(int n) {
  for (const Range& r : kRanges) {
    if (n >= r.first && n <= r.last) {
      return r.access;
    }
  }
  return VarAccess::Missing;
}

} // namespace mbc
