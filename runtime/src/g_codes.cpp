// The G code list of a FANUC 0i-MF (M series), sorted by number. Only the
// names are kept: which codes mbc executes is decided in nc_block.cpp.
#include "g_codes.h"

#include <mbc/g_codes.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace mbc::rt {

namespace {

constexpr std::array kGCodes = {
    GCodeInfo{0, "positioning"},
    GCodeInfo{10, "linear interpolation"},
    GCodeInfo{20, "circular interpolation CW"},
    GCodeInfo{22, "involute interpolation CW"},
    GCodeInfo{23, "exponential interpolation CW"},
    GCodeInfo{24, "3-dimensional circular interpolation CW"},
    GCodeInfo{30, "circular interpolation CCW"},
    GCodeInfo{32, "involute interpolation CCW"},
    GCodeInfo{33, "exponential interpolation CCW"},
    GCodeInfo{34, "3-dimensional circular interpolation CCW"},
    GCodeInfo{40, "dwell"},
    GCodeInfo{41, "G code preventing buffering"},
    GCodeInfo{50, "AI contour control / high-speed cycle machining"},
    GCodeInfo{51, "AI contour control"},
    GCodeInfo{54, "HRV3 on/off"},
    GCodeInfo{71, "cylindrical interpolation"},
    GCodeInfo{80, "AI contour control (advanced preview control)"},
    GCodeInfo{90, "exact stop"},
    GCodeInfo{100, "programmable data input"},
    GCodeInfo{106, "tool retract and recover"},
    GCodeInfo{110, "programmable data input mode cancel"},
    GCodeInfo{121, "polar coordinate interpolation mode"},
    GCodeInfo{131, "polar coordinate interpolation cancel mode"},
    GCodeInfo{150, "polar coordinates command cancel"},
    GCodeInfo{160, "polar coordinates command"},
    GCodeInfo{170, "XpYp plane selection"},
    GCodeInfo{180, "ZpXp plane selection"},
    GCodeInfo{190, "YpZp plane selection"},
    GCodeInfo{200, "input in inch"},
    GCodeInfo{210, "input in mm"},
    GCodeInfo{220, "stored stroke check function on"},
    GCodeInfo{230, "stored stroke check function off"},
    GCodeInfo{250, "spindle speed fluctuation detection off"},
    GCodeInfo{260, "spindle speed fluctuation detection on"},
    GCodeInfo{270, "reference position return check"},
    GCodeInfo{280, "reference position return"},
    GCodeInfo{282, "in-position check disable reference position return"},
    GCodeInfo{290, "movement from reference position"},
    GCodeInfo{300, "2nd, 3rd and 4th reference position return"},
    GCodeInfo{301, "floating reference position return"},
    GCodeInfo{310, "skip function"},
    GCodeInfo{318, "EGB skip"},
    GCodeInfo{330, "threading"},
    GCodeInfo{370, "automatic tool length measurement"},
    GCodeInfo{390, "corner circular interpolation"},
    GCodeInfo{400, "cutter compensation cancel"},
    GCodeInfo{401, "normal direction control cancel"},
    GCodeInfo{410, "cutter compensation left"},
    GCodeInfo{411, "normal direction control left"},
    GCodeInfo{420, "cutter compensation right"},
    GCodeInfo{421, "normal direction control right"},
    GCodeInfo{430, "tool length compensation +"},
    GCodeInfo{431, "tool length compensation in tool axis direction"},
    GCodeInfo{434, "tool center point control type 1"},
    GCodeInfo{435, "tool center point control type 2"},
    GCodeInfo{440, "tool length compensation -"},
    GCodeInfo{450, "tool offset increase"},
    GCodeInfo{460, "tool offset decrease"},
    GCodeInfo{470, "tool offset double increase"},
    GCodeInfo{480, "tool offset double decrease"},
    GCodeInfo{490, "tool length compensation cancel"},
    GCodeInfo{500, "scaling cancel"},
    GCodeInfo{501, "programmable mirror image cancel"},
    GCodeInfo{502, "polygon turning cancel"},
    GCodeInfo{510, "scaling"},
    GCodeInfo{511, "programmable mirror image"},
    GCodeInfo{512, "polygon turning"},
    GCodeInfo{520, "local coordinate system setting"},
    GCodeInfo{530, "machine coordinate system selection"},
    GCodeInfo{531, "tool axis direction control"},
    GCodeInfo{540, "workpiece coordinate system 1 selection"},
    GCodeInfo{541, "additional workpiece coordinate system selection"},
    GCodeInfo{542, "rotary table dynamic fixture offset"},
    GCodeInfo{550, "workpiece coordinate system 2 selection"},
    GCodeInfo{560, "workpiece coordinate system 3 selection"},
    GCodeInfo{570, "workpiece coordinate system 4 selection"},
    GCodeInfo{580, "workpiece coordinate system 5 selection"},
    GCodeInfo{590, "workpiece coordinate system 6 selection"},
    GCodeInfo{600, "single direction positioning"},
    GCodeInfo{610, "exact stop mode"},
    GCodeInfo{620, "automatic corner override"},
    GCodeInfo{630, "tapping mode"},
    GCodeInfo{640, "cutting mode"},
    GCodeInfo{650, "macro call"},
    GCodeInfo{660, "macro modal call A"},
    GCodeInfo{661, "macro modal call B"},
    GCodeInfo{670, "macro modal call cancel"},
    GCodeInfo{680, "coordinate system rotation"},
    GCodeInfo{682, "tilted working plane command"},
    GCodeInfo{690, "coordinate system rotation cancel"},
    GCodeInfo{730, "peck drilling cycle"},
    GCodeInfo{740, "left-hand tapping cycle"},
    GCodeInfo{760, "fine boring cycle"},
    GCodeInfo{800, "canned cycle cancel"},
    GCodeInfo{810, "drilling cycle, spot drilling"},
    GCodeInfo{820, "drilling cycle, counter boring"},
    GCodeInfo{830, "peck drilling cycle"},
    GCodeInfo{840, "tapping cycle"},
    GCodeInfo{842, "rigid tapping cycle (FS15 format)"},
    GCodeInfo{843, "left-hand rigid tapping cycle (FS15 format)"},
    GCodeInfo{850, "boring cycle"},
    GCodeInfo{860, "boring cycle"},
    GCodeInfo{870, "back boring cycle"},
    GCodeInfo{880, "boring cycle"},
    GCodeInfo{890, "boring cycle"},
    GCodeInfo{900, "absolute programming"},
    GCodeInfo{910, "incremental programming"},
    GCodeInfo{911, "maximum incremental amount check"},
    GCodeInfo{920, "workpiece coordinate system setting"},
    GCodeInfo{921, "workpiece coordinate system preset"},
    GCodeInfo{930, "inverse time feed"},
    GCodeInfo{940, "feed per minute"},
    GCodeInfo{950, "feed per revolution"},
    GCodeInfo{960, "constant surface speed control"},
    GCodeInfo{970, "constant surface speed control cancel"},
    GCodeInfo{980, "return to initial point in canned cycle"},
    GCodeInfo{990, "return to R point in canned cycle"},
    GCodeInfo{1070, "cylindrical interpolation"},
    GCodeInfo{1120, "polar coordinate interpolation mode"},
    GCodeInfo{1130, "polar coordinate interpolation cancel mode"},
};

static_assert(std::is_sorted(kGCodes.begin(), kGCodes.end(),
                             [](const GCodeInfo& a, const GCodeInfo& b) {
                               return a.tenths < b.tenths;
                             }));

} // namespace

const GCodeInfo* findGCode(int tenths) {
  const auto it = std::lower_bound(
      kGCodes.begin(), kGCodes.end(), tenths,
      [](const GCodeInfo& code, int value) { return code.tenths < value; });
  return it != kGCodes.end() && it->tenths == tenths ? &*it : nullptr;
}

std::string gCodeText(int tenths) {
  return tenths % 10 == 0 ? fmt::format("G{}", tenths / 10)
                          : fmt::format("G{}.{}", tenths / 10, tenths % 10);
}

} // namespace mbc::rt

bool mbc::isFanucGCode(int tenths) {
  return mbc::rt::findGCode(tenths) != nullptr;
}
