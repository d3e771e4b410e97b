// The handlers of the G code table (tables/g_codes.def): each executes one
// kind of row into the next modal state or the block, given the row's code.
// A new G code is a row there and, unless an existing handler does what it
// does, a handler here (CONTRIBUTING.md).
#include "g_code_handlers.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "canned_cycles.h"
#include "cutter_comp.h"
#include "frames.h"
#include "g_word.h"
#include "held_block.h"
#include "last_words.h"
#include "lathe_codes.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

using GCodeHandler = mbrt_status (*)(mbrt_ctx& ctx, ModalState& next,
                                     NcBlock& block, int code);

/// G00-G03; a group 01 code cancels the canned cycle.
mbrt_status setMotion(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.motion = code / 10;
  next.cycle = 0;
  return 0;
}

/// A lathe's G32 and G34 (lathe_codes.h), group 01 as G00-G03.
mbrt_status setThreading(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.motion = (code - kLatheOwnCode) / 10;
  next.cycle = 0;
  return 0;
}

/// A lathe's G90, G92 and G94 (lathe_cycles.h): a new cycle starts from no
/// end point; its own repeats keep it.
mbrt_status setSingleCycle(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  const int motion = (code - kLatheOwnCode) / 10;
  if (next.motion != motion) {
    next.singleCycle = SingleCycleData{};
  }
  next.motion = motion;
  next.cycle = 0;
  return 0;
}

/// Group 00 codes that act in their own block: G04, G28-G31, G39, G53, the
/// look-ahead switches and a lathe's G70-G76.
mbrt_status setNonModal(mbrt_ctx&, ModalState&, NcBlock& block, int code) {
  block.nonModal = code;
  return 0;
}

/// G43, G44, G49 (frames.h): the block's axis words may move with them.
mbrt_status setLengthCompensation(mbrt_ctx&, ModalState&, NcBlock& block,
                                  int code) {
  block.frames.lengthCode = code / 10;
  return 0;
}

mbrt_status cancelScaling(mbrt_ctx&, ModalState&, NcBlock& block, int) {
  block.frames.cancelScaling = true;
  return 0;
}

mbrt_status cancelRotation(mbrt_ctx&, ModalState&, NcBlock& block, int) {
  block.frames.cancelRotation = true;
  return 0;
}

/// G52, G92, G92.1, G51, G51.1, G50.1, G68 and G10 (frame_codes.h): the
/// block's words are their data, so one block holds one of them.
mbrt_status setFrameCode(mbrt_ctx& ctx, ModalState&, NcBlock& block, int code) {
  if (block.frames.code != 0) {
    const char column = gCodeColumn(ctx.profile);
    return raise(ctx, AlarmId::ImproperGCode,
                 fmt::format("{} and {} in one block",
                             gCodeText(columnTenths(column, block.frames.code)),
                             gCodeText(columnTenths(column, code))));
  }
  block.frames.code = code;
  return 0;
}

mbrt_status cancelCycle(mbrt_ctx&, ModalState& next, NcBlock&, int) {
  next.cycle = 0;
  return 0;
}

/// A mill's G73-G89 and a lathe's G83-G89 (canned_cycles.h).
mbrt_status startCycle(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.cycle = code % kLatheOwnCode / 10;
  next.seriesFifteenTap = 0;
  return 0;
}

/// The Series 15 format of rigid tapping: G84.2 and G84.3 are G84 and G74
/// with M29 given.
mbrt_status startSeriesFifteenTap(mbrt_ctx&, ModalState& next, NcBlock&,
                                  int code) {
  next.cycle = code == 842 ? 84 : 74;
  next.seriesFifteenTap = code;
  next.rigidTapping = true;
  return 0;
}

mbrt_status selectPlane(mbrt_ctx& ctx, ModalState& next, NcBlock&, int code) {
  if (code / 10 != ctx.machine.modal.plane && compensating(ctx)) {
    return raise(ctx, AlarmId::PlaneChangeInCrc,
                 fmt::format("G{} in cutter compensation mode (G{}); "
                             "cancel with G40 first",
                             code / 10, ctx.machine.modal.compensation));
  }
  next.plane = code / 10;
  return 0;
}

mbrt_status selectUnits(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.inch = code == 200;
  return 0;
}

mbrt_status selectDistance(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.incremental = code == 910;
  return 0;
}

mbrt_status selectReturn(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.returnToR = code == 990;
  return 0;
}

mbrt_status selectG541(mbrt_ctx& ctx, ModalState& next, NcBlock& block) {
  const double p = block.hasP ? block.p : 1.0;
  if (p < 1.0 || p > kG541Count) {
    return raise(ctx, AlarmId::ImproperNcAddress,
                 fmt::format("G54.1 P{}: P must be 1 to {}", p, kG541Count));
  }
  next.workOffset = kFirstG541Offset + static_cast<int>(p) - 1;
  block.selectsG541 = true;
  return 0;
}

/// G54-G59; G54 Pn is another spelling of G54.1 Pn.
mbrt_status selectWorkOffset(mbrt_ctx& ctx, ModalState& next, NcBlock& block,
                             int code) {
  if (code == 540 && block.hasP) {
    return selectG541(ctx, next, block);
  }
  next.workOffset = kFirstG54Offset + (code - 540) / 10;
  return 0;
}

mbrt_status selectAdditionalWorkOffset(mbrt_ctx& ctx, ModalState& next,
                                       NcBlock& block, int) {
  return selectG541(ctx, next, block);
}

/// G61-G64: exact stop, automatic corner override, tapping and cutting
/// mode, which change no path here.
mbrt_status selectCuttingMode(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.cuttingMode = code / 10;
  return 0;
}

/// G93-G95 (a lathe's G98 and G99 in system A).
mbrt_status selectFeedMode(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.feedMode = code / 10;
  return 0;
}

/// G15, G16: the polar coordinate command (polar.h).
mbrt_status selectPolar(mbrt_ctx&, ModalState& next, NcBlock&, int code) {
  next.polar = code == 160;
  return 0;
}

/// G40-G42 (cutter_comp.h): a code in the block starts or ends
/// compensation there.
mbrt_status selectCompensation(mbrt_ctx& ctx, ModalState& next, NcBlock&,
                               int code) {
  next.compensation = code / 10;
  ctx.compensation->codeInBlock = true;
  return 0;
}

/// G96 and G97 (spindle.h); a mill keeps G97.
mbrt_status selectSurfaceSpeed(mbrt_ctx&, ModalState& next, NcBlock&,
                               int code) {
  next.surfaceSpeed = code == 960;
  return 0;
}

/// Codes that change nothing mbc draws: G09 (the move ends at rest on the
/// same path), G11 outside the parameter input mode, G67 (callInsteadOfBlock
/// took the modal call off already) and a lathe's G69 (no mirror image for
/// double turrets is ever on).
mbrt_status withoutEffect(mbrt_ctx&, ModalState&, NcBlock&, int) {
  return 0;
}

/// G65, G66 and G66.1 are calls: the frontend makes G65 one, and
/// callInsteadOfBlock takes a block with G66 before its G codes apply.
mbrt_status takenByCalls(mbrt_ctx& ctx, ModalState&, NcBlock&, int code) {
  return raise(ctx, AlarmId::InternalError,
               fmt::format("{} reached the G code handlers", gCodeText(code)));
}

constexpr std::array kHandlers = {
#define G_CODE(M, A, B, C, Field, Code, Handler, Name) &Handler,
#define G_UNMODELLED(M, A, B, C, Name) static_cast<GCodeHandler>(nullptr),
#include "g_codes.def"
};

/// The codes the handlers execute, by row, for the path of most blocks.
constexpr std::array kCodes = {
#define G_CODE(M, A, B, C, Field, Code, Handler, Name) Code,
#define G_UNMODELLED(M, A, B, C, Name) kNo,
#include "g_codes.def"
};

/// Whether a row's handler sets one field of the modal state, the plane's
/// alarm under compensation aside: a block of these codes alone takes no
/// copy of the modal state. G20/G21 are not among them (the block's
/// coordinates change units), nor G66/G67 (callInsteadOfBlock takes the
/// block).
constexpr bool setsOneField(GCodeHandler handler) {
  return handler == &setMotion || handler == &selectPlane ||
         handler == &selectDistance || handler == &selectFeedMode ||
         handler == &selectCuttingMode || handler == &selectReturn ||
         handler == &selectPolar || handler == &selectCompensation ||
         handler == &selectSurfaceSpeed;
}

/// How a block of one-field codes runs a row: G00-G03 (setMotion) without a
/// call, the others through their handler; No: not one field.
enum class OneField : std::uint8_t { No, Motion, Handler };

constexpr auto kOneField = [] {
  std::array<OneField, kHandlers.size()> kinds{};
  for (std::size_t i = 0; i < kHandlers.size(); ++i) {
    kinds[i] = kHandlers[i] == &setMotion   ? OneField::Motion
               : setsOneField(kHandlers[i]) ? OneField::Handler
                                            : OneField::No;
  }
  return kinds;
}();

/// The row of a G word (tenths as written) in the profile's column, or -1.
int rowOf(const mbrt_ctx& ctx, double tenths) {
  return tenths >= 0.0 && tenths <= 9999.0
             ? findGCodeRowIndex(gCodeColumn(ctx.profile),
                                 static_cast<int>(tenths))
             : -1;
}

/// A lathe's G10 writes tool offsets (P X Z R Q), except G10 L2 and L20,
/// which write work offsets as on a mill.
bool writesWorkOffset(const mbrt_word* words, size_t count) {
  double l = 0.0;
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter == 'L') {
      l = roundHalfAway(numeric(words[i].value));
    }
  }
  return l == 2.0 || l == 20.0;
}

mbrt_status applyGCode(mbrt_ctx& ctx, ModalState& next, std::size_t row,
                       NcBlock& block) {
  return kHandlers[row](ctx, next, block, kCodes[row]);
}

} // namespace

void noteGCode(const mbrt_ctx& ctx, const mbrt_word& word, NcBlock& block) {
  if (block.gCodes == GCodes::Other) {
    return;
  }
  const int row = rowOf(ctx, gWordTenths(word.value));
  if (row < 0 || kOneField[static_cast<std::size_t>(row)] == OneField::No ||
      block.oneFieldCount == kMaxOneFieldCodes) {
    block.gCodes = GCodes::Other; // applyGCodes raises an alarm at it
    return;
  }
  block.gCodes = GCodes::OneField;
  block.oneField[block.oneFieldCount++] = static_cast<std::uint8_t>(row);
}

mbrt_status applyGCodes(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                        NcBlock& block) {
  if (block.gCodes == GCodes::None) {
    return 0; // most blocks: no modal state to copy
  }
  // G00-G03 also cancel a canned cycle: that takes the copy below.
  const auto isMotion = [](std::uint8_t row) {
    return kOneField[row] == OneField::Motion;
  };
  const std::uint8_t* oneField = block.oneField.data();
  const std::uint8_t* oneFieldEnd = oneField + block.oneFieldCount;
  if (block.gCodes == GCodes::OneField &&
      (ctx.machine.modal.cycle == 0 ||
       std::none_of(oneField, oneFieldEnd, isMotion))) {
    // Nothing to commit or drop: no copy of the modal state.
    for (const std::uint8_t* row = oneField; row != oneFieldEnd; ++row) {
      if (isMotion(*row)) {
        ctx.machine.modal.motion = kCodes[*row] / 10; // most of them, no call
      } else if (const mbrt_status status =
                     applyGCode(ctx, ctx.machine.modal, *row, block)) {
        return status; // G17-G19 under compensation
      }
    }
    return 0;
  }
  ModalState next = ctx.machine.modal;
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter != 'G') {
      continue;
    }
    const double written = gWordTenths(words[i].value);
    const int index = rowOf(ctx, written);
    if (index < 0) {
      return raise(ctx, AlarmId::ImproperGCode,
                   fmt::format("G{}", numeric(words[i].value)));
    }
    const auto row = static_cast<std::size_t>(index);
    if (kHandlers[row] == nullptr) {
      return raise(ctx, AlarmId::Unsupported,
                   fmt::format("{} ({})", gCodeText(static_cast<int>(written)),
                               gCodeRows()[row].name));
    }
    if (const mbrt_status status = applyGCode(ctx, next, row, block)) {
      return status;
    }
  }
  if (block.frames.code == kLatheG10 && writesWorkOffset(words, count)) {
    block.frames.code = 100;
  }
  const bool inch = next.inch;
  next.inch = ctx.machine.modal.inch;
  const int cycle = next.cycle;
  next.cycle = ctx.machine.modal.cycle;
  const bool newOrigin = next.workOffset != ctx.machine.modal.workOffset;
  if (newOrigin || inch != ctx.machine.modal.inch) {
    if (const mbrt_status status = refuseUnderHeldMoves(
            ctx, newOrigin ? "a work coordinate system change" : "G20/G21")) {
      return status;
    }
  }
  ctx.machine.modal = next;
  if (block.selectsG541) {
    ctx.machine.lastWords[lastWordSlot(LastWord::G541P)] =
        block.hasP ? block.p : 1.0;
  }
  if (newOrigin) {
    resyncProgram(ctx); // the machine stays, the program position moves
  }
  switchUnits(ctx, inch);
  changeCycle(ctx, cycle);
  return 0;
}

int modalCode(const mbrt_ctx& ctx, ModalField field) {
  const ModalState& modal = ctx.machine.modal;
  switch (field) {
    case ModalField::None:
      return kNo;
    case ModalField::Motion: // a lathe's G32 and single cycles are its own
      return modal.motion <= 3 ? modal.motion * 10
                               : latheOwn(modal.motion * 10);
    case ModalField::Plane:
      return modal.plane * 10;
    case ModalField::Distance:
      return modal.incremental ? 910 : 900;
    case ModalField::Feed:
      return modal.feedMode * 10;
    case ModalField::Units:
      return modal.inch ? 200 : 210;
    case ModalField::Compensation:
      return modal.compensation * 10;
    case ModalField::Length:
      return ctx.machine.frames.lengthMode * 10;
    case ModalField::Cycle:
      if (modal.cycle == 0) {
        return 800;
      }
      if (ctx.profile.lathe()) {
        return latheOwn(modal.cycle * 10);
      }
      return modal.seriesFifteenTap != 0 ? modal.seriesFifteenTap
                                         : modal.cycle * 10;
    case ModalField::Return:
      return modal.returnToR ? 990 : 980;
    case ModalField::Scaling:
      return ctx.machine.frames.scaling ? 510 : 500;
    case ModalField::ModalCall:
      return ctx.stack.modalCalls.empty()             ? 670
             : ctx.stack.modalCalls.back().everyBlock ? 661
                                                      : 660;
    case ModalField::SurfaceSpeed:
      return modal.surfaceSpeed ? 960 : 970;
    case ModalField::WorkOffset:
      return modal.workOffset < kFirstG541Offset
                 ? 540 + (modal.workOffset - kFirstG54Offset) * 10
                 : 541;
    case ModalField::CuttingMode:
      return modal.cuttingMode * 10;
    case ModalField::Rotation:
      return ctx.machine.frames.rotation ? 680 : 690;
    case ModalField::Polar:
      return modal.polar ? 160 : 150;
    case ModalField::Mirror:
      return ctx.machine.frames.mirrorMask != 0 ? 511 : 501;
    case ModalField::TurretMirror: // never on
      return latheOwn(690);
  }
  return kNo;
}

double modalGroupValue(const mbrt_ctx& ctx, int group) {
  const ModalField field = groupField(group, ctx.profile.lathe());
  if (field == ModalField::None) {
    return 0.0;
  }
  const char column = gCodeColumn(ctx.profile);
  const GCodeRow* row = findModalRow(column, field, modalCode(ctx, field));
  return row != nullptr ? row->tenths(column) / 10.0 : 0.0;
}

} // namespace mbc::rt
