// The G code list of a FANUC 0i-TF in its three G code systems (the
// Operator's Manual for lathe systems, "G code list"), with the codes mbc
// executes marked: a code it does not stops the run with MBC0001.
#include "lathe_codes.h"

#include <mbc/g_codes.h>

#include <array>

#include "block_calls.h"

namespace mbc::rt {

namespace {

constexpr int kNone = kNoLatheCode;

constexpr int own(int tenths) {
  return kLatheOwnCode + tenths;
}

constexpr std::array kLatheGCodes = {
    LatheGCode{0, 0, 0, 0, true, "positioning"},
    LatheGCode{10, 10, 10, 10, true, "linear interpolation"},
    LatheGCode{20, 20, 20, 20, true, "circular interpolation CW"},
    LatheGCode{22, 22, 22, own(22), false, "involute interpolation CW"},
    LatheGCode{30, 30, 30, 30, true, "circular interpolation CCW"},
    LatheGCode{32, 32, 32, own(32), false, "involute interpolation CCW"},
    LatheGCode{40, 40, 40, 40, true, "dwell"},
    LatheGCode{41, 41, 41, own(41), false, "G code preventing buffering"},
    LatheGCode{50, 50, 50, own(50), false, "high-speed cycle machining"},
    LatheGCode{51, 51, 51, 51, true, "AI contour control"},
    LatheGCode{54, 54, 54, 54, true, "HRV3 on/off"},
    LatheGCode{70, 70, 70, own(70), false, "hypothetical axis interpolation"},
    LatheGCode{71, 71, 71, 71, false, "cylindrical interpolation"},
    LatheGCode{80, 80, 80, 80, true, "advanced preview control"},
    LatheGCode{90, 90, 90, 90, true, "exact stop"},
    LatheGCode{100, 100, 100, kLatheG10, true,
               "programmable data input (tool offsets)"},
    LatheGCode{106, 106, 106, own(106), false, "tool retract and recover"},
    LatheGCode{109, 109, 109, own(109), false,
               "programmable diameter/radius switching"},
    LatheGCode{110, 110, 110, 110, true, "programmable data input cancel"},
    LatheGCode{121, 121, 121, 121, false,
               "polar coordinate interpolation mode"},
    LatheGCode{131, 131, 131, 131, false,
               "polar coordinate interpolation cancel mode"},
    LatheGCode{170, 170, 170, 170, true, "XpYp plane selection"},
    LatheGCode{180, 180, 180, 180, true, "ZpXp plane selection"},
    LatheGCode{190, 190, 190, 190, true, "YpZp plane selection"},
    LatheGCode{200, 200, 700, 200, true, "input in inch"},
    LatheGCode{210, 210, 710, 210, true, "input in mm"},
    LatheGCode{220, 220, 220, 220, false, "stored stroke check function on"},
    LatheGCode{230, 230, 230, 230, false, "stored stroke check function off"},
    LatheGCode{250, 250, 250, 250, false,
               "spindle speed fluctuation detection off"},
    LatheGCode{260, 260, 260, 260, false,
               "spindle speed fluctuation detection on"},
    LatheGCode{270, 270, 270, 270, false, "reference position return check"},
    LatheGCode{280, 280, 280, 280, true, "reference position return"},
    LatheGCode{282, 282, 282, own(282), false,
               "reference position return without in-position check"},
    LatheGCode{300, 300, 300, 300, true,
               "2nd, 3rd and 4th reference position return"},
    LatheGCode{301, 301, 301, 301, false, "floating reference position return"},
    LatheGCode{310, 310, 310, 310, true, "skip function"},
    LatheGCode{318, 318, 318, own(318), false, "EGB skip"},
    LatheGCode{320, 330, 330, kLatheThreading, true, "threading"},
    LatheGCode{340, 340, 340, own(340), true, "variable-lead threading"},
    LatheGCode{360, 360, 360, own(360), false,
               "automatic tool offset (X axis)"},
    LatheGCode{370, 370, 370, own(370), false,
               "automatic tool offset (Z axis)"},
    LatheGCode{371, 371, 371, own(371), false,
               "automatic tool offset (X axis, with circular threading)"},
    LatheGCode{372, 372, 372, own(372), false,
               "automatic tool offset (Z axis, with circular threading)"},
    LatheGCode{390, 390, 390, own(390), false,
               "corner circular interpolation (tool nose radius compensation)"},
    LatheGCode{400, 400, 400, 400, true,
               "tool nose radius compensation cancel"},
    LatheGCode{410, 410, 410, 410, true, "tool nose radius compensation left"},
    LatheGCode{420, 420, 420, 420, true, "tool nose radius compensation right"},
    LatheGCode{500, 920, 920, 920, true,
               "coordinate system setting, maximum spindle speed"},
    LatheGCode{502, 2500, 2500, own(502), false, "polygon turning cancel"},
    LatheGCode{503, 921, 921, 921, true, "workpiece coordinate system preset"},
    LatheGCode{512, 2510, 2510, own(512), false, "polygon turning"},
    LatheGCode{520, 520, 520, 520, true, "local coordinate system setting"},
    LatheGCode{530, 530, 530, 530, true, "machine coordinate system selection"},
    LatheGCode{540, 540, 540, 540, true,
               "workpiece coordinate system 1 selection"},
    LatheGCode{541, 541, 541, own(541), false,
               "additional workpiece coordinate system selection"},
    LatheGCode{550, 550, 550, 550, true,
               "workpiece coordinate system 2 selection"},
    LatheGCode{560, 560, 560, 560, true,
               "workpiece coordinate system 3 selection"},
    LatheGCode{570, 570, 570, 570, true,
               "workpiece coordinate system 4 selection"},
    LatheGCode{580, 580, 580, 580, true,
               "workpiece coordinate system 5 selection"},
    LatheGCode{590, 590, 590, 590, true,
               "workpiece coordinate system 6 selection"},
    LatheGCode{610, 610, 610, 610, true, "exact stop mode"},
    LatheGCode{630, 630, 630, 630, true, "tapping mode"},
    LatheGCode{640, 640, 640, 640, true, "cutting mode"},
    LatheGCode{650, 650, 650, 650, true, "macro call"},
    LatheGCode{660, 660, 660, 660, true, "macro modal call A"},
    LatheGCode{661, 661, 661, 661, true, "macro modal call B"},
    LatheGCode{670, 670, 670, 670, true, "macro modal call cancel"},
    LatheGCode{680, 680, 680, own(680), false,
               "mirror image for double turrets on"},
    LatheGCode{690, 690, 690, own(690), true,
               "mirror image for double turrets off"},
    LatheGCode{700, 700, 720, own(700), true, "finishing cycle"},
    LatheGCode{710, 710, 730, own(710), true, "stock removal in turning"},
    LatheGCode{720, 720, 740, own(720), true, "stock removal in facing"},
    LatheGCode{730, 730, 750, own(730), true, "pattern repeating cycle"},
    LatheGCode{740, 740, 760, own(740), true, "end face peck drilling cycle"},
    LatheGCode{750, 750, 770, own(750), true,
               "outer diameter/internal diameter drilling cycle"},
    LatheGCode{760, 760, 780, own(760), true, "multiple-thread cutting cycle"},
    LatheGCode{800, 800, 800, 800, true, "canned cycle for drilling cancel"},
    LatheGCode{830, 830, 830, own(830), true, "cycle for face drilling"},
    LatheGCode{840, 840, 840, own(840), true, "cycle for face tapping"},
    LatheGCode{842, 842, 842, own(842), false,
               "rigid tapping cycle (FS15 format)"},
    LatheGCode{850, 850, 850, own(850), true, "cycle for face boring"},
    LatheGCode{870, 870, 870, own(870), true, "cycle for side drilling"},
    LatheGCode{880, 880, 880, own(880), true, "cycle for side tapping"},
    LatheGCode{890, 890, 890, own(890), true, "cycle for side boring"},
    LatheGCode{900, 770, 200, kLatheTurningCycle, true,
               "outer diameter/internal diameter cutting cycle"},
    LatheGCode{920, 780, 210, kLatheThreadCycle, true, "threading cycle"},
    LatheGCode{930, 930, 930, own(930), false, "inverse time feed"},
    LatheGCode{940, 790, 240, kLatheFacingCycle, true,
               "end face turning cycle"},
    LatheGCode{960, 960, 960, 960, true, "constant surface speed control"},
    LatheGCode{970, 970, 970, 970, true,
               "constant surface speed control cancel"},
    LatheGCode{980, 940, 940, 940, true, "feed per minute"},
    LatheGCode{990, 950, 950, 950, true, "feed per revolution"},
    LatheGCode{1070, 1070, 1070, own(1070), false,
               "cylindrical interpolation (G07.1)"},
    LatheGCode{1120, 1120, 1120, own(1120), false,
               "polar coordinate interpolation mode (G12.1)"},
    LatheGCode{1130, 1130, 1130, own(1130), false,
               "polar coordinate interpolation cancel mode (G13.1)"},
    LatheGCode{kNone, 900, 900, 900, true, "absolute programming"},
    LatheGCode{kNone, 910, 910, 910, true, "incremental programming"},
    LatheGCode{kNone, 980, 980, 980, true, "return to initial level"},
    LatheGCode{kNone, 990, 990, 990, true, "return to R point level"},
};

int systemTenths(const LatheGCode& row, char system) {
  return system == 'C' ? row.c : system == 'B' ? row.b : row.a;
}

const LatheGCode* findByCode(int code) {
  for (const LatheGCode& row : kLatheGCodes) {
    if (row.code == code) {
      return &row;
    }
  }
  return nullptr;
}

} // namespace

std::span<const LatheGCode> latheGCodeList() {
  return kLatheGCodes;
}

int systemCode(char system, int code) {
  const LatheGCode* row = findByCode(code);
  return row != nullptr ? systemTenths(*row, system) : kNone;
}

double writtenLatheCode(const mbrt_ctx& ctx, int code) {
  const int tenths = systemCode(ctx.profile.gCodeSystem, code);
  return tenths != kNone ? tenths / 10.0 : 0.0;
}

int latheCode(char system, int tenths) {
  for (const LatheGCode& row : kLatheGCodes) {
    if (systemTenths(row, system) == tenths) {
      return row.code;
    }
  }
  return kNone;
}

const char* unmodelledLatheCode(int code) {
  const LatheGCode* row = findByCode(code);
  return row != nullptr && !row->modelled ? row->name : nullptr;
}

double latheModalGroupValue(const mbrt_ctx& ctx, int group) {
  const ModalState& modal = ctx.modal;
  const bool systemA = ctx.profile.gCodeSystem == 'A';
  switch (group) {
    case 1: // G32 and the single cycles in system A's numbers
      return modal.motion > 3
                 ? writtenLatheCode(ctx, kLatheOwnCode + modal.motion * 10)
                 : modal.motion;
    case 2:
      return modal.surfaceSpeed ? 96 : 97;
    case 3: // system A tells absolute from incremental by address
      return systemA ? 0 : modal.incremental ? 91 : 90;
    case 4:
      return 69;
    case 5:
      return writtenLatheCode(ctx, modal.feedMode * 10);
    case 6:
      return writtenLatheCode(ctx, modal.inch ? 200 : 210);
    case 7:
      return modal.compensation;
    case 10: // G80, or a drilling cycle by its lathe number
      return modal.cycle == 0
                 ? 80
                 : writtenLatheCode(ctx, kLatheOwnCode + modal.cycle * 10);
    case 11:
      return systemA ? 0 : modal.returnToR ? 99 : 98;
    case 12:
      return modalCallGroupValue(ctx);
    case 14:
      return modal.workOffset < kFirstG541Offset ? 53 + modal.workOffset : 54.1;
    case 15:
      return modal.cuttingMode;
    case 16:
      return modal.plane;
    default:
      return 0;
  }
}

} // namespace mbc::rt

namespace mbc {

int latheFunction(char system, int tenths) {
  const int code = rt::latheCode(system, tenths);
  return code < 0 ? -1 : rt::systemCode('A', code);
}

const char* unmodelledLatheFunction(int aTenths) {
  return rt::unmodelledLatheCode(rt::latheCode('A', aTenths));
}

} // namespace mbc
