// The G code list of a FANUC 0i-MF (M series), sorted by number, with the
// codes mbc executes marked: a code it does not stops the run with MBC0001
// (nc_block.cpp), and mbc check reports it (a unit test keeps the two in
// step).
#include "g_codes.h"

#include <mbc/g_codes.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace mbc::rt {

namespace {

constexpr std::array kGCodes = {
    GCodeInfo{0, true, "positioning"},
    GCodeInfo{10, true, "linear interpolation"},
    GCodeInfo{20, true, "circular interpolation CW"},
    GCodeInfo{22, false, "involute interpolation CW"},
    GCodeInfo{23, false, "exponential interpolation CW"},
    GCodeInfo{24, false, "3-dimensional circular interpolation CW"},
    GCodeInfo{30, true, "circular interpolation CCW"},
    GCodeInfo{32, false, "involute interpolation CCW"},
    GCodeInfo{33, false, "exponential interpolation CCW"},
    GCodeInfo{34, false, "3-dimensional circular interpolation CCW"},
    GCodeInfo{40, true, "dwell"},
    GCodeInfo{41, false, "G code preventing buffering"},
    GCodeInfo{50, true, "AI contour control / high-speed cycle machining"},
    GCodeInfo{51, true, "AI contour control"},
    GCodeInfo{54, true, "HRV3 on/off"},
    GCodeInfo{62, false, "NURBS interpolation"},
    GCodeInfo{70, false, "hypothetical axis interpolation"},
    GCodeInfo{71, false, "cylindrical interpolation"},
    GCodeInfo{80, true, "AI contour control (advanced preview control)"},
    GCodeInfo{90, true, "exact stop"},
    GCodeInfo{100, true, "programmable data input"},
    GCodeInfo{106, false, "tool retract and recover"},
    GCodeInfo{109, false, "programmable diameter/radius switching"},
    GCodeInfo{110, true, "programmable data input mode cancel"},
    GCodeInfo{121, false, "polar coordinate interpolation mode"},
    GCodeInfo{124, false, "groove cutting by continuous circles CW"},
    GCodeInfo{131, false, "polar coordinate interpolation cancel mode"},
    GCodeInfo{134, false, "groove cutting by continuous circles CCW"},
    GCodeInfo{150, true, "polar coordinates command cancel"},
    GCodeInfo{160, true, "polar coordinates command"},
    GCodeInfo{170, true, "XpYp plane selection"},
    GCodeInfo{171, false, "plane conversion"},
    GCodeInfo{180, true, "ZpXp plane selection"},
    GCodeInfo{190, true, "YpZp plane selection"},
    GCodeInfo{200, true, "input in inch"},
    GCodeInfo{210, true, "input in mm"},
    GCodeInfo{220, false, "stored stroke check function on"},
    GCodeInfo{230, false, "stored stroke check function off"},
    GCodeInfo{250, false, "spindle speed fluctuation detection off"},
    GCodeInfo{260, false, "spindle speed fluctuation detection on"},
    GCodeInfo{270, false, "reference position return check"},
    GCodeInfo{280, true, "reference position return"},
    GCodeInfo{282, false,
              "in-position check disable reference position return"},
    GCodeInfo{290, true, "movement from reference position"},
    GCodeInfo{300, true, "2nd, 3rd and 4th reference position return"},
    GCodeInfo{301, false, "floating reference position return"},
    GCodeInfo{302, false,
              "2nd-4th reference position return without in-position check"},
    GCodeInfo{310, true, "skip function"},
    GCodeInfo{311, false, "multi-step skip 1"},
    GCodeInfo{312, false, "multi-step skip 2"},
    GCodeInfo{313, false, "multi-step skip 3"},
    GCodeInfo{314, false, "multi-step skip 4"},
    GCodeInfo{318, false, "EGB skip"},
    GCodeInfo{319, false, "continuous high-speed skip"},
    GCodeInfo{330, false, "threading"},
    GCodeInfo{340, false, "variable-lead threading"},
    GCodeInfo{350, false, "circular threading CW"},
    GCodeInfo{360, false, "circular threading CCW"},
    GCodeInfo{370, false, "automatic tool length measurement"},
    GCodeInfo{380, false, "cutter compensation vector retention"},
    GCodeInfo{390, true, "corner circular interpolation"},
    GCodeInfo{400, true, "cutter compensation cancel"},
    GCodeInfo{401, false, "normal direction control cancel"},
    GCodeInfo{410, true, "cutter compensation left"},
    GCodeInfo{411, false, "normal direction control left"},
    GCodeInfo{412, false, "3-dimensional cutter compensation left (tool side)"},
    GCodeInfo{413, false, "3-dimensional cutter compensation (leading edge)"},
    GCodeInfo{414, false,
              "3-dimensional cutter compensation left (FS16i format)"},
    GCodeInfo{415, false,
              "3-dimensional cutter compensation left (FS16i format, variant)"},
    GCodeInfo{416, false, "3-dimensional cutter compensation left (type 2)"},
    GCodeInfo{420, true, "cutter compensation right"},
    GCodeInfo{421, false, "normal direction control right"},
    GCodeInfo{422, false,
              "3-dimensional cutter compensation right (tool side)"},
    GCodeInfo{424, false,
              "3-dimensional cutter compensation right (FS16i format)"},
    GCodeInfo{
        425, false,
        "3-dimensional cutter compensation right (FS16i format, variant)"},
    GCodeInfo{426, false, "3-dimensional cutter compensation right (type 2)"},
    GCodeInfo{430, true, "tool length compensation +"},
    GCodeInfo{431, false, "tool length compensation in tool axis direction"},
    GCodeInfo{434, false, "tool center point control type 1"},
    GCodeInfo{435, false, "tool center point control type 2"},
    GCodeInfo{437, false, "tool offset (lathe form on a machining center)"},
    GCodeInfo{438, false, "cutting point command type 1"},
    GCodeInfo{439, false, "cutting point command type 2"},
    GCodeInfo{440, true, "tool length compensation -"},
    GCodeInfo{450, false, "tool offset increase"},
    GCodeInfo{460, false, "tool offset decrease"},
    GCodeInfo{470, false, "tool offset double increase"},
    GCodeInfo{480, false, "tool offset double decrease"},
    GCodeInfo{490, true, "tool length compensation cancel"},
    GCodeInfo{491, false,
              "tool length compensation cancel (tool axis direction)"},
    GCodeInfo{500, true, "scaling cancel"},
    GCodeInfo{501, true, "programmable mirror image cancel"},
    GCodeInfo{502, false, "polygon turning cancel"},
    GCodeInfo{510, true, "scaling"},
    GCodeInfo{511, true, "programmable mirror image"},
    GCodeInfo{512, false, "polygon turning"},
    GCodeInfo{520, true, "local coordinate system setting"},
    GCodeInfo{530, true, "machine coordinate system selection"},
    GCodeInfo{531, false, "tool axis direction control"},
    GCodeInfo{536, false, "tool center point retention"},
    GCodeInfo{540, true, "workpiece coordinate system 1 selection"},
    GCodeInfo{541, true, "additional workpiece coordinate system selection"},
    GCodeInfo{542, false, "rotary table dynamic fixture offset"},
    GCodeInfo{544, false, "workpiece setting error compensation"},
    GCodeInfo{550, true, "workpiece coordinate system 2 selection"},
    GCodeInfo{560, true, "workpiece coordinate system 3 selection"},
    GCodeInfo{570, true, "workpiece coordinate system 4 selection"},
    GCodeInfo{580, true, "workpiece coordinate system 5 selection"},
    GCodeInfo{590, true, "workpiece coordinate system 6 selection"},
    GCodeInfo{600, false, "single direction positioning"},
    GCodeInfo{610, true, "exact stop mode"},
    GCodeInfo{620, true, "automatic corner override"},
    GCodeInfo{630, true, "tapping mode"},
    GCodeInfo{640, true, "cutting mode"},
    GCodeInfo{650, true, "macro call"},
    GCodeInfo{660, true, "macro modal call A"},
    GCodeInfo{661, true, "macro modal call B"},
    GCodeInfo{670, true, "macro modal call cancel"},
    GCodeInfo{680, true, "coordinate system rotation"},
    GCodeInfo{682, false, "tilted working plane command"},
    GCodeInfo{683, false, "tilted working plane by tool axis direction"},
    GCodeInfo{684, false, "tilted working plane, incremental"},
    GCodeInfo{690, true, "coordinate system rotation cancel"},
    GCodeInfo{707, false, "finishing cycle (turning on a machining center)"},
    GCodeInfo{717, false, "stock removal in turning (on a machining center)"},
    GCodeInfo{721, false, "figure copying, rotation"},
    GCodeInfo{722, false, "figure copying, parallel shift"},
    GCodeInfo{727, false, "stock removal in facing (on a machining center)"},
    GCodeInfo{730, true, "peck drilling cycle"},
    GCodeInfo{737, false, "pattern repeating cycle (on a machining center)"},
    GCodeInfo{740, true, "left-hand tapping cycle"},
    GCodeInfo{747, false,
              "end face peck drilling cycle (on a machining center)"},
    GCodeInfo{750, false, "plunge grinding cycle"},
    GCodeInfo{757, false, "grooving cycle (on a machining center)"},
    GCodeInfo{760, true, "fine boring cycle"},
    GCodeInfo{767, false, "multiple threading cycle (on a machining center)"},
    GCodeInfo{770, false, "direct constant-dimension plunge grinding cycle"},
    GCodeInfo{780, false, "continuous-feed surface grinding cycle"},
    GCodeInfo{790, false, "intermittent-feed surface grinding cycle"},
    GCodeInfo{800, true, "canned cycle cancel"},
    GCodeInfo{804, false, "electronic gear box synchronization cancel"},
    GCodeInfo{805, false, "electronic gear box 2 pairs cancel"},
    GCodeInfo{810, true, "drilling cycle, spot drilling"},
    GCodeInfo{811, false, "chopping"},
    GCodeInfo{814, false, "electronic gear box synchronization start"},
    GCodeInfo{815, false, "electronic gear box 2 pairs start"},
    GCodeInfo{820, true, "drilling cycle, counter boring"},
    GCodeInfo{830, true, "peck drilling cycle"},
    GCodeInfo{840, true, "tapping cycle"},
    GCodeInfo{842, true, "rigid tapping cycle (FS15 format)"},
    GCodeInfo{843, true, "left-hand rigid tapping cycle (FS15 format)"},
    GCodeInfo{850, true, "boring cycle"},
    GCodeInfo{860, true, "boring cycle"},
    GCodeInfo{870, true, "back boring cycle"},
    GCodeInfo{880, true, "boring cycle"},
    GCodeInfo{890, true, "boring cycle"},
    GCodeInfo{900, true, "absolute programming"},
    GCodeInfo{910, true, "incremental programming"},
    GCodeInfo{911, false, "maximum incremental amount check"},
    GCodeInfo{920, true, "workpiece coordinate system setting"},
    GCodeInfo{921, true, "workpiece coordinate system preset"},
    GCodeInfo{930, true, "inverse time feed"},
    GCodeInfo{940, true, "feed per minute"},
    GCodeInfo{950, true, "feed per revolution"},
    GCodeInfo{960, false, "constant surface speed control"},
    GCodeInfo{961, false, "spindle indexing, waiting for completion"},
    GCodeInfo{962, false, "spindle indexing, not waiting"},
    GCodeInfo{963, false, "spindle indexing completion check"},
    GCodeInfo{964, false, "SV speed control mode on"},
    GCodeInfo{970, true, "constant surface speed control cancel"},
    GCodeInfo{980, true, "return to initial point in canned cycle"},
    GCodeInfo{990, true, "return to R point in canned cycle"},
    GCodeInfo{1070, false, "cylindrical interpolation"},
    GCodeInfo{1120, false, "polar coordinate interpolation mode"},
    GCodeInfo{1130, false, "polar coordinate interpolation cancel mode"},
};

static_assert(std::is_sorted(kGCodes.begin(), kGCodes.end(),
                             [](const GCodeInfo& a, const GCodeInfo& b) {
                               return a.tenths < b.tenths;
                             }));

} // namespace

std::span<const GCodeInfo> millGCodeList() {
  return kGCodes;
}

const GCodeInfo* findGCode(int tenths) {
  const auto it = std::lower_bound(
      kGCodes.begin(), kGCodes.end(), tenths,
      [](const GCodeInfo& code, int value) { return code.tenths < value; });
  return it != kGCodes.end() && it->tenths == tenths ? &*it : nullptr;
}

} // namespace mbc::rt

std::string mbc::gCodeText(int tenths) {
  return tenths % 10 == 0 ? fmt::format("G{}", tenths / 10)
                          : fmt::format("G{}.{}", tenths / 10, tenths % 10);
}

bool mbc::isFanucGCode(int tenths) {
  return mbc::rt::findGCode(tenths) != nullptr;
}

const char* mbc::unmodelledGCode(int tenths) {
  const mbc::rt::GCodeInfo* code = mbc::rt::findGCode(tenths);
  return code != nullptr && !code->modelled ? code->name : nullptr;
}
