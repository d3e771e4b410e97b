// The parameters mbc models. Bit parameters take the whole byte (bit 0 = 1).
#include "parameters.h"

#include <mbc/calling_codes.h>

#include <array>

namespace mbc::rt {

namespace {

constexpr double kMaxCode = 99'999'999.0;

/// The parameters that make codes call: whole numbers, 0 = no code.
constexpr ParameterSpec codeTableSpec(const CodeTable& table, double low,
                                      double high) {
  return {table.firstParameter,
          table.firstParameter + table.size - 1,
          low,
          high,
          0,
          true};
}

constexpr std::array kParameters = {
    // 2nd, 3rd and 4th reference positions (G30), machine coordinates, mm.
    ParameterSpec{1241, 1243, -999999, 999999, 0, false, true},
    // Stored stroke check 1: the + and - ends of each axis's stroke, machine
    // coordinates. Unset, 1320 is below 1321: FANUC's infinite stroke.
    ParameterSpec{1320, 1320, -999999, 999999, -999999, false, true},
    ParameterSpec{1321, 1321, -999999, 999999, 999999, false, true},
    ParameterSpec{1, 1, 0, 255, 0, true},                 // #1 FCV (lathe)
    ParameterSpec{1006, 1006, 0, 255, 0, true, true},     // #0 ROT: rotary axis
    ParameterSpec{1008, 1008, 0, 255, 0, true, true},     // #0 ROA, #1 RAB
    ParameterSpec{1260, 1260, 0, 999999, 0, false, true}, // deg per turn
    ParameterSpec{3401, 3401, 0, 255, 0, true},           // #0 DPI
    ParameterSpec{3402, 3402, 0, 255, 0, true},      // #4 FPM (lathe), #6 CLR
    ParameterSpec{3403, 3403, 0, 255, 0, true},      // #5 CIR
    ParameterSpec{3405, 3405, 0, 255, 0, true},      // #4 CCR (lathe)
    ParameterSpec{3410, 3410, 0, 1e9, 0.02, false},  // arc radius tolerance
    ParameterSpec{3772, 3772, 0, 99999999, 0, true}, // maximum spindle speed
    // A lathe's multiple repetitive cycles, until a program's first cycle
    // block gives them: 5130 G76 chamfer (0.1 lead), 5131 its angle, 5132
    // and 5133 G71/G72 depth and escape, 5135 and 5136 G73 relief, 5137 G73
    // divisions, 5139 G74/G75 return, 5140 G76 least depth, 5141 G76
    // finishing allowance (mm), 5142 finishing passes, 5143 tool angle.
    ParameterSpec{5130, 5130, 0, 99, 0, true},
    ParameterSpec{5131, 5131, 0, 89, 0, true},
    ParameterSpec{5132, 5136, -1e6, 1e6, 0, false},
    ParameterSpec{5137, 5137, 1, 99999999, 1, true},
    ParameterSpec{5139, 5141, 0, 1e6, 0, false},
    ParameterSpec{5142, 5142, 1, 99, 1, true},
    ParameterSpec{5143, 5143, 0, 120, 0, true},
    ParameterSpec{5001, 5001, 0, 255, 0, true},     // #0 TLC, #1 TLB
    ParameterSpec{5003, 5003, 0, 255, 0, true},     // #0 SUP, #1 SUV: CRC start
    ParameterSpec{5008, 5008, 0, 255, 0, true},     // #1 CNC, #3 CNV: CRC check
    ParameterSpec{5101, 5101, 0, 255, 0, true},     // #2 RTR, #4 RD1, #5 RD2
    ParameterSpec{5114, 5115, 0, 1000, 0.1, false}, // peck retract, G83 gap
    ParameterSpec{5200, 5200, 0, 255, 0, true},     // #0 G84, #5 PCP: rigid
    ParameterSpec{5210, 5210, 0, kMaxCode, 29, true}, // rigid tapping M code
    ParameterSpec{5213, 5213, 0, 1000, 0.1, false},   // rigid peck return
    ParameterSpec{5400, 5400, 0, 255, 0, true},       // #0 RIN, #6 XSC, #7 SCR
    ParameterSpec{5410, 5410, -360000, 360000, 0, true}, // G68 angle, 0.001 deg
    ParameterSpec{5411, 5411, 0, 999999, 0, true},       // G51 magnification
    ParameterSpec{6000, 6000, 0, 255, 0, true},          // #3 V15
    ParameterSpec{6001, 6001, 0, 255, 0, true},          // #1 PRT, #5 TCS
    ParameterSpec{6004, 6004, 0, 255, 0, true},          // #0 NAT
    ParameterSpec{6007, 6007, 0, 255, 0, true},          // #4 BCS, #5 SCS
    ParameterSpec{19607, 19607, 0, 255, 0, true}, // #2 CCC, #5 CAV: CRC corners
    ParameterSpec{19625, 19625, 0, 8, 3, true},   // CRC look-ahead blocks
    // G codes calling O9010..O9019; negative: a modal (G66-like) call.
    codeTableSpec(kCustomGCodes, -9999, 9999),
    codeTableSpec(kSubprogramMCodes, 0, kMaxCode),
    codeTableSpec(kMacroMCodes, 0, kMaxCode),
};

} // namespace

std::span<const ParameterSpec> parameterSpecs() {
  return kParameters;
}

const ParameterSpec* findParameter(int number) {
  for (const ParameterSpec& spec : kParameters) {
    if (number >= spec.first && number <= spec.last) {
      return &spec;
    }
  }
  return nullptr;
}

} // namespace mbc::rt
