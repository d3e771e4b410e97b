// The system variable table: one row per range of numbers with its reader
// and, when writable, its writer (spec §6, Part A). Readers get the index of
// the number within its range.
#include "sysvars.h"

#include <mbc/arith.h>
#include <mbc/signals.h>
#include <mbc/sysvars.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string_view>

#include "block_calls.h"
#include "cutter_comp.h"
#include "flat_gcode.h"
#include "frames.h"
#include "g_code_handlers.h"
#include "held_block.h"
#include "lathe_offset_vars.h"
#include "machine_unit.h"
#include "offset_keys.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

using Reader = mbrt_status (*)(mbrt_ctx& ctx, int index, Num* out);
using Writer = mbrt_status (*)(mbrt_ctx& ctx, int index, Num value,
                               const char* comment);

/// One row of the control's system variable map (docs/control-tables.md is
/// printed from these rows).
struct SysVarRange {
  long first;
  long last;
  const char* meaning;
  Reader read;            // nullptr: the control has it, mbc does not (PS0115)
  Writer write;           // nullptr: read-only (PS0116)
  bool byProfile = false; // missing on the default machine (#2401-#2800)
  const char* note = nullptr; // why a reader gives what it gives, or why not
  const char* unit = nullptr; // what the numbers are in, for lengths
};

/// Positions and work offsets read in the unit the program is in.
constexpr const char* kAxisUnit =
    "the program's unit (G21 mm, G20 inch), degrees on a rotary axis";
/// Tool offsets hold the numbers they were set to: G20/G21 does not
/// convert them.
constexpr const char* kOffsetUnit =
    "the unit they were set in: G20/G21 does not convert them";

/// Offsets are 20 numbers apart per coordinate system, one per axis.
constexpr int kOffsetStride = 20;

mbrt_status readZero(mbrt_ctx&, int, Num* out) {
  *out = 0.0;
  return 0;
}

/// #3100-#3102, the system constants of a 30i-B: vacant (as #0), pi and e.
mbrt_status readConstant(mbrt_ctx&, int index, Num* out) {
  constexpr std::array<double, 3> kConstants = {0.0, std::numbers::pi,
                                                std::numbers::e};
  *out = index == 0 ? vacant() : kConstants[static_cast<std::size_t>(index)];
  return 0;
}

/// #1000 + i is bit i of the word #1032 (spec §6.1): one input signal, 0 or
/// 1, as the profile or a preset sets it (there is no PMC).
mbrt_status readInputSignal(mbrt_ctx& ctx, int index, Num* out) {
  *out = static_cast<double>((ctx.data.inputWords[0] >> index) & 1U);
  return 0;
}

/// #1032-#1035: UI000-UI031, UI100-UI131, UI200-UI231, UI300-UI331 as
/// signed 32-bit numbers.
mbrt_status readInputWord(mbrt_ctx& ctx, int index, Num* out) {
  *out = static_cast<double>(
      static_cast<std::int32_t>(ctx.data.inputWords[index]));
  return 0;
}

/// #1100 + i is bit i of the word #1132 (spec §6.1): one signal, 0 or 1.
mbrt_status readOutputSignal(mbrt_ctx& ctx, int index, Num* out) {
  *out = static_cast<double>((ctx.data.outputWords[0] >> index) & 1U);
  return 0;
}

mbrt_status writeOutputSignal(mbrt_ctx& ctx, int index, Num value,
                              const char*) {
  const double v = numeric(value);
  if (v != 0.0 && v != 1.0) {
    return raise(
        ctx, AlarmId::ArgumentOutOfRange,
        fmt::format("#{} is one signal: 0 or 1, not {}", 1100 + index, v));
  }
  const std::uint32_t bit = 1U << index;
  ctx.data.outputWords[0] =
      v != 0.0 ? ctx.data.outputWords[0] | bit : ctx.data.outputWords[0] & ~bit;
  return 0;
}

/// 32 signals as one signed 32-bit number.
mbrt_status readOutputWord(mbrt_ctx& ctx, int index, Num* out) {
  *out = static_cast<double>(
      static_cast<std::int32_t>(ctx.data.outputWords[index]));
  return 0;
}

mbrt_status writeOutputWord(mbrt_ctx& ctx, int index, Num value, const char*) {
  const double v = roundHalfAway(numeric(value));
  if (!isSignalWord(v)) {
    return raise(ctx, AlarmId::ArgumentOutOfRange,
                 fmt::format("#{} holds 32 signals: {} is no 32-bit number",
                             1132 + index, numeric(value)));
  }
  ctx.data.outputWords[index] =
      static_cast<std::uint32_t>(static_cast<std::int32_t>(v));
  return 0;
}

/// The tool offset variables come in four series, #2001/#10001,
/// #2201/#11001, #2401/#12001 and #2601/#13001 (the #2xxx form for offsets
/// 1-200); what each holds depends on the offset memory type and on
/// parameter 6000#3 V15 (docs/machine-profile.md). nullptr: the series does
/// not exist on this machine.
using OffsetField = double ToolOffset::*;

OffsetField offsetSeries(const Profile& profile, int series, bool shortForm) {
  static constexpr OffsetField kStandard[4] = {
      &ToolOffset::hWear, &ToolOffset::hGeometry, &ToolOffset::dWear,
      &ToolOffset::dGeometry};
  // V15: numbered as on a Series 15, geometry before wear, D in #2401+.
  static constexpr OffsetField kSeries15[4] = {
      &ToolOffset::hGeometry, &ToolOffset::hWear, &ToolOffset::dGeometry,
      &ToolOffset::dWear};
  const bool v15 = profile.v15;
  const OffsetField* layout = v15 ? kSeries15 : kStandard;
  switch (profile.toolOffsetMemory) {
    case 'A': // one value per offset, for H and D
      return series == 0 ? &ToolOffset::hGeometry : nullptr;
    case 'B': // geometry and wear, shared by H and D
      return series < 2 ? layout[series] : nullptr;
    default:
      return shortForm && series >= 2 && !v15 ? nullptr : layout[series];
  }
}

/// Series `Series` of the tool offsets (short form: #2xxx), offset number
/// index + 1; beyond the profile's count, or a series the machine does not
/// have, is PS0115.
template <int Series, bool ShortForm>
mbrt_status findToolOffset(mbrt_ctx& ctx, int index, OffsetField* field) {
  *field = offsetSeries(ctx.profile, Series, ShortForm);
  if (*field == nullptr) {
    const int first = ShortForm ? 2001 + Series * 200 : 10001 + Series * 1000;
    const bool v15Would =
        ShortForm && Series >= 2 && ctx.profile.toolOffsetMemory == 'C';
    return raise(ctx, AlarmId::VariableOutOfRange,
                 fmt::format("#{}: no such tool offset variable with offset "
                             "memory {}{}",
                             first + index, ctx.profile.toolOffsetMemory,
                             v15Would ? " (#2401-#2800 are the D offsets with "
                                        "parameter 6000#3 V15)"
                                      : ""));
  }
  if (index + 1 > ctx.profile.toolOffsetCount) {
    return raise(ctx, AlarmId::VariableOutOfRange,
                 fmt::format("tool offset {} (the machine has {})", index + 1,
                             ctx.profile.toolOffsetCount));
  }
  return 0;
}

template <int Series, bool ShortForm>
mbrt_status readToolOffset(mbrt_ctx& ctx, int index, Num* out) {
  OffsetField field = nullptr;
  if (const mbrt_status status =
          findToolOffset<Series, ShortForm>(ctx, index, &field)) {
    return status;
  }
  *out = ctx.data.toolOffsets[index + 1].*field;
  return 0;
}

/// Offset memory holds least increments, like the work offsets.
template <int Series, bool ShortForm>
mbrt_status writeToolOffset(mbrt_ctx& ctx, int index, Num value, const char*) {
  OffsetField field = nullptr;
  if (const mbrt_status status =
          findToolOffset<Series, ShortForm>(ctx, index, &field)) {
    return status;
  }
  const double counts = roundToCounts(numeric(value), ctx.inputScale());
  if (!fitsAddress(counts)) {
    return raise(ctx, AlarmId::ArgumentOutOfRange,
                 fmt::format("tool offset {}", numeric(value)));
  }
  const double units =
      countsToUnits(static_cast<Counts>(counts), ctx.inputScale());
  ctx.data.toolOffsets[index + 1].*field = units;
  flattenToolOffset(ctx, millOffsetKey(field).l, index + 1, units);
  return 0;
}

/// #2801-#2999 hold a lathe's geometry offsets (lathe_offset_vars.h, read
/// before this table); a mill has none.
mbrt_status refuseLatheOffset(mbrt_ctx& ctx, int index) {
  return raise(ctx, AlarmId::VariableOutOfRange,
               fmt::format("#{} (a lathe's tool offset: a profile with "
                           "\"series\": \"T\" has it)",
                           2801 + index));
}

mbrt_status readLatheOnly(mbrt_ctx& ctx, int index, Num*) {
  return refuseLatheOffset(ctx, index);
}

mbrt_status writeLatheOnly(mbrt_ctx& ctx, int index, Num, const char*) {
  return refuseLatheOffset(ctx, index);
}

/// #98000-#98499: commons a profile with "common_98000" has.
mbrt_status findCommon98000(mbrt_ctx& ctx, int index) {
  if (!ctx.profile.commons98000) {
    return raise(ctx, AlarmId::VariableOutOfRange,
                 fmt::format("#{} (a profile with \"common_98000\" has it)",
                             kFirstCommon98000 + index));
  }
  return 0;
}

mbrt_status readCommon98000(mbrt_ctx& ctx, int index, Num* out) {
  if (const mbrt_status status = findCommon98000(ctx, index)) {
    return status;
  }
  *out = ctx.data.commons98000[static_cast<std::size_t>(index)];
  return 0;
}

mbrt_status writeCommon98000(mbrt_ctx& ctx, int index, Num value, const char*) {
  if (const mbrt_status status = findCommon98000(ctx, index)) {
    return status;
  }
  ctx.data.commons98000[static_cast<std::size_t>(index)] = value;
  return 0;
}

/// What the control shows of an alarm or message text.
std::string messageText(const char* comment) {
  return std::string(trimmedMessage(comment != nullptr ? comment : "")
                         .substr(0, kMessageShown));
}

mbrt_status writeMacroAlarm(mbrt_ctx& ctx, int, Num value,
                            const char* comment) {
  const double n = roundHalfAway(numeric(value));
  if (n < 0.0 || n > kMacroAlarmLast) {
    return raise(ctx, AlarmId::ArgumentOutOfRange,
                 fmt::format("#{} = {} (0 to {})", kMacroAlarmVariable, n,
                             kMacroAlarmLast));
  }
  return raise(ctx, AlarmId::MacroAlarm, messageText(comment),
               kMacroAlarmVariable + static_cast<int>(n));
}

mbrt_status writeMessage(mbrt_ctx& ctx, int, Num, const char* comment) {
  sendMessage(ctx, messageText(comment));
  return 0;
}

mbrt_status readClockMs(mbrt_ctx& ctx, int, Num* out) {
  *out = std::floor(ctx.machine.clockMs);
  return 0;
}

mbrt_status writeClockMs(mbrt_ctx& ctx, int, Num value, const char*) {
  ctx.machine.clockMs = numeric(value);
  return 0;
}

mbrt_status readClockHours(mbrt_ctx& ctx, int, Num* out) {
  *out = ctx.machine.clockHours;
  return 0;
}

mbrt_status writeClockHours(mbrt_ctx& ctx, int, Num value, const char*) {
  ctx.machine.clockHours = numeric(value);
  return 0;
}

/// A plain read/write number of the context.
/// A number a part of the context holds: `Part` of the context, `Field`
/// of the part.
template <auto Part, auto Field>
mbrt_status readField(mbrt_ctx& ctx, int, Num* out) {
  *out = (ctx.*Part).*Field;
  return 0;
}

template <auto Part, auto Field>
mbrt_status writeField(mbrt_ctx& ctx, int, Num value, const char*) {
  (ctx.*Part).*Field = numeric(value);
  return 0;
}

/// #3003 and #3004 hold bit patterns 0..Max.
template <auto Part, auto Field, int Max>
mbrt_status writeBits(mbrt_ctx& ctx, int, Num value, const char*) {
  const double bits = roundHalfAway(numeric(value));
  if (bits < 0.0 || bits > Max) {
    return raise(ctx, AlarmId::ArgumentOutOfRange,
                 fmt::format("{} (0 to {})", bits, Max));
  }
  (ctx.*Part).*Field = bits;
  return 0;
}

mbrt_status readMainProgram(mbrt_ctx& ctx, int, Num* out) {
  *out = ctx.stack.mainProgramNumber;
  return 0;
}

mbrt_status readModalGroup(mbrt_ctx& ctx, int index, Num* out) {
  *out = modalGroupValue(ctx, index + 1);
  return 0;
}

/// #4101..#4130: the last value of each address; #4115 is the program.
mbrt_status readLastWord(mbrt_ctx& ctx, int index, Num* out) {
  *out = index == static_cast<int>(LastWord::Program)
             ? ctx.programNumber()
             : ctx.machine.lastWords[static_cast<std::size_t>(index)];
  return 0;
}

/// Axes beyond the machine's read 0.
template <Counts (*Position)(const mbrt_ctx&, int)>
mbrt_status readPosition(mbrt_ctx& ctx, int axis, Num* out) {
  *out = axis < ctx.axisCount()
             ? countsToUnits(ctx.shown(axis, Position(ctx, axis)),
                             ctx.axisScale(axis))
             : 0.0;
  return 0;
}

/// #5001: the block end point as the program commanded it.
Counts blockEndPosition(const mbrt_ctx& ctx, int axis) {
  return programPosition(ctx)[axis];
}

/// #5021.., #5041..: the tool position stops the look-ahead, so a move
/// cutter compensation holds leaves first (cutter_comp.h).
template <Counts (*Position)(const mbrt_ctx&, int)>
mbrt_status readToolPosition(mbrt_ctx& ctx, int axis, Num* out) {
  if (const mbrt_status status = stopLookAhead(ctx)) {
    return status;
  }
  return readPosition<Position>(ctx, axis, out);
}

Counts machinePosition(const mbrt_ctx& ctx, int axis) {
  return ctx.machine.position[axis];
}

Counts currentPosition(const mbrt_ctx& ctx, int axis) {
  return localPosition(ctx)[axis];
}

Counts skipPosition(const mbrt_ctx& ctx, int axis) {
  return ctx.machine.skipPosition[axis];
}

/// #5081+: the tool length offset, or a lathe's tool position offset.
Counts toolLengthOffset(const mbrt_ctx& ctx, int axis) {
  return (axis == ctx.machine.frames.lengthAxis ? ctx.machine.frames.length
                                                : 0) +
         ctx.machine.frames.toolGeometry[axis] +
         ctx.machine.frames.toolWear[axis];
}

/// Axes beyond the machine's read 0 and ignore writes, so that programs
/// written for a machine with more axes still run.
mbrt_status readOffset(mbrt_ctx& ctx, int offset, int axis, Num* out) {
  *out = axis < ctx.axisCount()
             ? countsToUnits(workOffsetInForce(ctx, offset, axis),
                             ctx.axisScale(axis))
             : 0.0;
  return 0;
}

mbrt_status writeOffset(mbrt_ctx& ctx, int offset, int axis, Num value) {
  if (axis >= ctx.axisCount()) {
    return 0;
  }
  if (const mbrt_status status =
          refuseUnderCompensation(ctx, "writing a work offset")) {
    return status;
  }
  if (const mbrt_status status =
          offset == ctx.machine.modal.workOffset || offset == kExternalOffset
              ? refuseUnderHeldCorner(ctx, "writing the work offset in force")
              : 0) {
    return status;
  }
  const double counts = roundToAxisCounts(ctx, axis, numeric(value));
  if (!fitsAddress(counts)) {
    return raise(ctx, AlarmId::ArgumentOutOfRange,
                 fmt::format("work offset {}", numeric(value)));
  }
  // The machine position stays; the workpiece position follows the offset.
  storeWorkOffset(ctx, offset, axis, static_cast<Counts>(counts));
  resyncProgram(ctx);
  flattenWorkOffset(ctx, offset);
  return 0;
}

/// #5201..#5340: external offset, then G54..G59.
mbrt_status readG54Offset(mbrt_ctx& ctx, int index, Num* out) {
  return readOffset(ctx, index / kOffsetStride, index % kOffsetStride, out);
}

mbrt_status writeG54Offset(mbrt_ctx& ctx, int index, Num value, const char*) {
  return writeOffset(ctx, index / kOffsetStride, index % kOffsetStride, value);
}

/// #7001.. and #14001..: G54.1 P1.. (#14001.. has only 8 axes per set).
template <int AxesPerSet>
mbrt_status readG541Offset(mbrt_ctx& ctx, int index, Num* out) {
  const int axis = index % kOffsetStride;
  if (axis >= AxesPerSet) {
    return raise(ctx, AlarmId::VariableOutOfRange, "no such axis");
  }
  return readOffset(ctx, kFirstG541Offset + index / kOffsetStride, axis, out);
}

template <int AxesPerSet>
mbrt_status writeG541Offset(mbrt_ctx& ctx, int index, Num value, const char*) {
  const int axis = index % kOffsetStride;
  if (axis >= AxesPerSet) {
    return raise(ctx, AlarmId::VariableOutOfRange, "no such axis");
  }
  return writeOffset(ctx, kFirstG541Offset + index / kOffsetStride, axis,
                     value);
}

constexpr const char* kNoInterrupts =
    "macro interrupts (M96) are not modelled: nothing interrupts a run";
constexpr const char* kExtendedNumbers =
    "the 30i-B's extended variable numbers are not modelled: mbc reads the "
    "classic numbers";

constexpr std::array kSystemVariables = {
    SysVarRange{1000, 1031, "interface input signals UI000-UI031, a bit each",
                readInputSignal, nullptr, false,
                "as the profile or --set gives them (no PMC)"},
    SysVarRange{1032, 1035, "input signals as 32-bit words", readInputWord,
                nullptr},
    SysVarRange{1100, 1131, "interface output signals UO000-UO031, a bit each",
                readOutputSignal, writeOutputSignal},
    SysVarRange{1132, 1135, "output signals as 32-bit words", readOutputWord,
                writeOutputWord},
    SysVarRange{2001, 2200, "tool offsets 1-200, 1st set (#10001+)",
                readToolOffset<0, true>, writeToolOffset<0, true>, false,
                nullptr, kOffsetUnit},
    SysVarRange{2201, 2400, "tool offsets 1-200, 2nd set (#11001+)",
                readToolOffset<1, true>, writeToolOffset<1, true>, false,
                nullptr, kOffsetUnit},
    SysVarRange{2401, 2600, "tool offsets 1-200, 3rd set (#12001+)",
                readToolOffset<2, true>, writeToolOffset<2, true>, true,
                "with 6000#3 V15", kOffsetUnit},
    SysVarRange{2601, 2800, "tool offsets 1-200, 4th set (#13001+)",
                readToolOffset<3, true>, writeToolOffset<3, true>, true,
                "with 6000#3 V15", kOffsetUnit},
    SysVarRange{2801, 2999, "tool offsets of a lathe (T series)", readLatheOnly,
                writeLatheOnly, true, "on a lathe"},
    SysVarRange{3000, 3000, "macro alarm #3000=n (MESSAGE)", readZero,
                writeMacroAlarm},
    SysVarRange{3001, 3001, "clock 1, milliseconds", readClockMs, writeClockMs,
                false, "the run's modelled time"},
    SysVarRange{3002, 3002, "clock 2, hours", readClockHours, writeClockHours,
                false, "the run's modelled time"},
    SysVarRange{3003, 3003, "single block and FIN wait control",
                readField<&mbrt_ctx::run, &RunControl::singleBlockBits>,
                writeBits<&mbrt_ctx::run, &RunControl::singleBlockBits, 3>},
    SysVarRange{3004, 3004, "feed hold, override and exact stop control",
                readField<&mbrt_ctx::run, &RunControl::feedHoldBits>,
                writeBits<&mbrt_ctx::run, &RunControl::feedHoldBits, 7>},
    SysVarRange{3005, 3005, "setting data",
                readField<&mbrt_ctx::data, &MachineData::settingBits>,
                writeField<&mbrt_ctx::data, &MachineData::settingBits>},
    SysVarRange{3006, 3006, "message stop #3006=1 (MESSAGE)", readZero,
                writeMessage, false, "the run goes on"},
    SysVarRange{3007, 3007, "mirror image state", readZero, nullptr, false,
                "0: no external mirror image signals"},
    SysVarRange{3008, 3008, "program restart in progress", readZero, nullptr,
                false, "0: a run never restarts"},
    SysVarRange{3011, 3011, "date YYYYMMDD",
                readField<&mbrt_ctx::run, &RunControl::date>, nullptr},
    SysVarRange{3012, 3012, "time HHMMSS",
                readField<&mbrt_ctx::run, &RunControl::timeOfDay>, nullptr},
    SysVarRange{3100, 3102, "system constants: vacant, pi, e", readConstant,
                nullptr},
    SysVarRange{3901, 3901, "machined parts",
                readField<&mbrt_ctx::data, &MachineData::partsCount>,
                writeField<&mbrt_ctx::data, &MachineData::partsCount>},
    SysVarRange{3902, 3902, "required parts",
                readField<&mbrt_ctx::data, &MachineData::partsRequired>,
                writeField<&mbrt_ctx::data, &MachineData::partsRequired>},
    SysVarRange{4000, 4000, "main program number", readMainProgram, nullptr},
    // Execution is sequential (Part A), so the "executing block" variables
    // #4201.. and #4301.. read the same as #4001.. and #4101...
    SysVarRange{4001, 4030, "modal G codes of groups 1-30, block read",
                readModalGroup, nullptr},
    SysVarRange{4101, 4130, "last B D E F H M N O S T P words, block read",
                readLastWord, nullptr},
    SysVarRange{4201, 4230, "modal G codes, block executing", readModalGroup,
                nullptr, false, "as #4001+: blocks run one by one"},
    SysVarRange{4301, 4330, "last words, block executing", readLastWord,
                nullptr, false, "as #4101+: blocks run one by one"},
    SysVarRange{4401, 4430, "modal G codes of the block an interrupt stopped",
                nullptr, nullptr, false, kNoInterrupts},
    SysVarRange{4501, 4530, "last words of the block an interrupt stopped",
                nullptr, nullptr, false, kNoInterrupts},
    SysVarRange{5001, 5020, "block end position, workpiece coordinates",
                readPosition<blockEndPosition>, nullptr, false, nullptr,
                kAxisUnit},
    SysVarRange{5021, 5040, "current position, machine coordinates",
                readToolPosition<machinePosition>, nullptr, false, nullptr,
                kAxisUnit},
    SysVarRange{5041, 5060, "current position, workpiece coordinates",
                readToolPosition<currentPosition>, nullptr, false, nullptr,
                kAxisUnit},
    SysVarRange{5061, 5080, "skip signal position (G31)",
                readPosition<skipPosition>, nullptr, false, nullptr, kAxisUnit},
    SysVarRange{5081, 5100, "tool length offset in force",
                readPosition<toolLengthOffset>, nullptr, false, nullptr,
                kAxisUnit},
    SysVarRange{5101, 5120, "servo position deviation", readZero, nullptr,
                false, "0: the modelled axes follow exactly"},
    SysVarRange{5121, 5140, "manual handle interruption amount", readZero,
                nullptr, false, "0: no handle turns in a run"},
    SysVarRange{5201, 5340, "external and G54-G59 work offsets", readG54Offset,
                writeG54Offset, false, nullptr, kAxisUnit},
    SysVarRange{7001, 7960, "G54.1 P1-P48 work offsets",
                readG541Offset<kOffsetStride>, writeG541Offset<kOffsetStride>,
                false, nullptr, kAxisUnit},
    SysVarRange{8400, 8499, "tool life management data", nullptr, nullptr,
                false, "mbc keeps no tool life data"},
    SysVarRange{8550, 8579, "tool management data", nullptr, nullptr, false,
                "mbc keeps no tool management data"},
    SysVarRange{10001, 10999, "tool offsets 1-999, 1st set",
                readToolOffset<0, false>, writeToolOffset<0, false>, false,
                nullptr, kOffsetUnit},
    SysVarRange{11001, 11999, "tool offsets 1-999, 2nd set",
                readToolOffset<1, false>, writeToolOffset<1, false>, false,
                nullptr, kOffsetUnit},
    SysVarRange{12001, 12999, "tool offsets 1-999, 3rd set",
                readToolOffset<2, false>, writeToolOffset<2, false>, false,
                nullptr, kOffsetUnit},
    SysVarRange{13001, 13999, "tool offsets 1-999, 4th set",
                readToolOffset<3, false>, writeToolOffset<3, false>, false,
                nullptr, kOffsetUnit},
    SysVarRange{14001, 19988, "G54.1 P1-P300 work offsets",
                readG541Offset<MBRT_MAX_AXES>, writeG541Offset<MBRT_MAX_AXES>,
                false, nullptr, kAxisUnit},
    SysVarRange{kFirstCommon98000, kLastCommon98000,
                "additional common variables (option)", readCommon98000,
                writeCommon98000, true, "\"common_98000\" in the profile"},
    SysVarRange{100000, 199999, "extended system variable numbers (30i-B)",
                nullptr, nullptr, false, kExtendedNumbers},
    SysVarRange{500000, 999999, "extended system variable numbers (30i-B)",
                nullptr, nullptr, false, kExtendedNumbers},
};

/// A variable of the control's map that mbc does not model: PS0115 with
/// what it is and why.
mbrt_status refuseAbsent(mbrt_ctx& ctx, const SysVarRange& range, long n) {
  return raise(ctx, AlarmId::VariableOutOfRange,
               fmt::format("#{} ({}): {}", n, range.meaning, range.note));
}

const SysVarRange* findSystemVariable(long n) {
  const auto it =
      std::upper_bound(kSystemVariables.begin(), kSystemVariables.end(), n,
                       [](long number, const SysVarRange& range) {
                         return number < range.first;
                       });
  if (it == kSystemVariables.begin()) {
    return nullptr;
  }
  const SysVarRange& range = *std::prev(it);
  return n <= range.last ? &range : nullptr;
}

} // namespace

bool setInputSignal(mbrt_ctx& ctx, int number, double value) {
  if (number >= kFirstInputSignal && number < kFirstInputWord) {
    if (value != 0.0 && value != 1.0) {
      return false;
    }
    const std::uint32_t bit = 1U << (number - kFirstInputSignal);
    ctx.data.inputWords[0] = value != 0.0 ? ctx.data.inputWords[0] | bit
                                          : ctx.data.inputWords[0] & ~bit;
    return true;
  }
  if (number >= kFirstInputWord && number <= kLastInputWord &&
      isSignalWord(value)) {
    ctx.data.inputWords[number - kFirstInputWord] =
        static_cast<std::uint32_t>(static_cast<std::int32_t>(value));
    return true;
  }
  return false;
}

} // namespace mbc::rt

namespace mbc {

// The compile-time view of the same table, for the default machine: a
// system variable without a writer is read-only.
VarAccess variableAccess(int n) {
  if (n == 0) {
    return VarAccess::ReadOnly;
  }
  if (isLocal(n) || isFixedCommon(n)) {
    return VarAccess::ReadWrite;
  }
  if (n <= kLastNonvolatile) {
    return VarAccess::Missing;
  }
  const rt::SysVarRange* range = rt::findSystemVariable(n);
  if (range == nullptr || range->byProfile || range->read == nullptr) {
    return VarAccess::Missing;
  }
  return range->write ? VarAccess::ReadWrite : VarAccess::ReadOnly;
}

bool unmodelledVariable(int n, UnmodelledVariable* out) {
  const rt::SysVarRange* range = rt::findSystemVariable(n);
  if (range == nullptr || range->read != nullptr) {
    return false;
  }
  *out = {range->meaning, range->note};
  return true;
}

namespace {

SystemVariableFacts factsOf(const rt::SysVarRange& range) {
  return {range.first,
          range.last,
          range.meaning,
          range.read != nullptr,
          range.write != nullptr,
          range.byProfile,
          range.note,
          range.unit};
}

} // namespace

std::optional<SystemVariableFacts> systemVariableFacts(int n) {
  const rt::SysVarRange* range = rt::findSystemVariable(n);
  if (range == nullptr) {
    return std::nullopt;
  }
  return factsOf(*range);
}

std::vector<SystemVariableFacts> systemVariableRows() {
  std::vector<SystemVariableFacts> rows;
  for (const rt::SysVarRange& range : rt::kSystemVariables) {
    rows.push_back(factsOf(range));
  }
  return rows;
}

bool dependsOnProfile(int n) {
  if (n >= kFirstExtendedCommon && n <= kLastExtendedCommon) {
    return true;
  }
  const rt::SysVarRange* range = rt::findSystemVariable(n);
  return range != nullptr && range->byProfile;
}

} // namespace mbc

namespace mbc::rt {

mbrt_status readSystemVariable(mbrt_ctx& ctx, long n, Num* out) {
  if (ctx.profile.lathe() && isLatheOffsetNumber(n)) {
    return readLatheOffset(ctx, n, out);
  }
  const SysVarRange* range = findSystemVariable(n);
  if (range == nullptr) {
    return raise(ctx, AlarmId::VariableOutOfRange, fmt::format("#{}", n));
  }
  if (range->read == nullptr) {
    return refuseAbsent(ctx, *range, n);
  }
  return range->read(ctx, static_cast<int>(n - range->first), out);
}

mbrt_status writeSystemVariable(mbrt_ctx& ctx, long n, Num value,
                                const char* comment) {
  if (ctx.profile.lathe() && isLatheOffsetNumber(n)) {
    return writeLatheOffset(ctx, n, value);
  }
  const SysVarRange* range = findSystemVariable(n);
  if (range == nullptr) {
    return raise(ctx, AlarmId::VariableOutOfRange, fmt::format("#{}", n));
  }
  if (range->read == nullptr) {
    return refuseAbsent(ctx, *range, n);
  }
  if (range->write == nullptr) {
    return raise(ctx, AlarmId::WriteProtectedVariable, fmt::format("#{}", n));
  }
  return range->write(ctx, static_cast<int>(n - range->first), value, comment);
}

} // namespace mbc::rt
