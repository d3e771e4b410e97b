// NC blocks (spec §1.5, §5.8, Part A): address values to counts or
// integers, modal G codes, the last-value words of #4101.., motion, and the
// flow the block asks for (M98, M99, M02/M30, M00/M01, block_calls.h).
#include <mbc/arith.h>

#include <fmt/format.h>

#include <algorithm>

#include "block_calls.h"
#include "canned_cycles.h"
#include "corner_blends.h"
#include "corner_state.h"
#include "cutter_comp.h"
#include "cutter_comp_state.h"
#include "flat_gcode.h"
#include "frame_codes.h"
#include "frames.h"
#include "g_code_handlers.h"
#include "g_word.h"
#include "held_block.h"
#include "lathe_codes.h"
#include "lathe_corners.h"
#include "lathe_repetitive.h"
#include "lathe_settings.h"
#include "lathe_shapes.h"
#include "lathe_tools.h"
#include "look_ahead.h"
#include "motion.h"
#include "parameter_input.h"
#include "polar.h"
#include "programmed_moves.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

constexpr int kMaxMCodes = 3;
constexpr double kMaxCodeValue = 99'999'999.0; // M, S, T...: 8 digits

/// An axis or arc word in counts, `perIncrement` of them to each of the
/// `increments` per unit: a literal without decimal point already is
/// increments (unless 3401#0), everything else is rounded to the increment.
mbrt_status toCounts(mbrt_ctx& ctx, const mbrt_word& word, double increments,
                     int perIncrement, Counts* out) {
  const double value = numeric(word.value);
  const double counts =
      word.kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
          ? value
          : roundToCounts(value, increments);
  if (!fitsAddress(counts)) {
    return raise(ctx, AlarmId::TooManyDigits,
                 fmt::format("{}{}", word.letter, value));
  }
  *out = static_cast<Counts>(counts) * perIncrement;
  return 0;
}

/// A radius, arc centre or depth word (R, I, J, K, Q) in counts.
mbrt_status toLengthCounts(mbrt_ctx& ctx, const mbrt_word& word, Counts* out) {
  return toCounts(ctx, word, ctx.inputScale(), ctx.countsPerIncrement(), out);
}

mbrt_status readMCode(mbrt_ctx& ctx, double value, BlockCodes& codes) {
  if (codes.mCount == kMaxMCodes) {
    return raise(ctx, AlarmId::ImproperNcAddress,
                 fmt::format("more than {} M codes in one block", kMaxMCodes));
  }
  codes.m[codes.mCount++] = static_cast<int>(value);
  // The rigid tapping M code (5210, M29) makes the next G84/G74 rigid.
  if (value == ctx.profile.rigidTappingCode) {
    ctx.machine.modal.rigidTapping = true;
  }
  return 0;
}

/// Every word but G, P and L, in program order.
/// ,C ,R (a chamfer or corner R, not both) and ,A.
mbrt_status readCommaWord(mbrt_ctx& ctx, const mbrt_word& word,
                          MotionWords& motion) {
  if (word.letter == commaWordLetter('A')) {
    const double perUnit = addressCountsPerUnit(ctx, word.letter);
    const double value = numeric(word.value);
    motion.angle =
        word.kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
            ? value / perUnit
            : roundToCounts(value, perUnit) / perUnit;
    return 0;
  }
  const char blend = word.letter == commaWordLetter('C') ? 'C' : 'R';
  if (motion.blend != 0 && motion.blend != blend) {
    return raise(ctx, AlarmId::TooManyAddressCommands,
                 ",C and ,R in one block: a chamfer or a corner R");
  }
  motion.blend = blend;
  return toLengthCounts(ctx, word, &motion.blendAmount);
}

/// A word a one-shot code reads its own way, or nothing for the common
/// reading: G04's X and U (seconds), and in the Series 10/11 format the A
/// (G76's tool angle) and D (G71-G76: depth, divisions or relief, least
/// increments or times without a decimal point) of one-block cycles.
std::optional<mbrt_status> readOneShotWord(mbrt_ctx& ctx, const mbrt_word& word,
                                           NcBlock& block) {
  const char letter = word.letter;
  const double value = numeric(word.value);
  if (block.nonModal == 40 && (letter == 'X' || letter == 'U')) {
    // X1.5 is 1.5 s; X1500 counts milliseconds, like P, unless literals
    // are whole units (3401#0 DPI).
    block.dwellSeconds =
        word.kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
            ? value / 1000.0
            : value;
    return 0;
  }
  // G71-G73 read U and W as their own words (depth of cut, finishing
  // allowances, relief); in G code systems B and C, where U and W are no
  // axes, the cycle block is the only place they mean anything.
  const bool shapeCycle = block.nonModal >= kLatheOwnCode + 710 &&
                          block.nonModal <= kLatheOwnCode + 730;
  if (shapeCycle && (letter == 'U' || letter == 'W') &&
      ctx.profile.gCodeSystem != 'A') {
    return 0;
  }
  const bool seriesTenCycle = block.nonModal >= kLatheOwnCode + 710 &&
                              block.nonModal <= kLatheOwnCode + 760 &&
                              seriesTenFormat(ctx);
  if (seriesTenCycle && letter == 'A' &&
      block.nonModal == kLatheOwnCode + 760) {
    block.tenFormatA = value;
    return 0;
  }
  if (seriesTenCycle && letter == 'D') {
    if (word.kind == MBRT_WORD_DEC_LITERAL) {
      return raise(ctx, AlarmId::IllegalDecimalPoint,
                   fmt::format("{}: D takes a whole number in G{}",
                               pointedWordText('D', value),
                               writtenLatheCode(ctx.profile.gCodeSystem,
                                                block.nonModal)));
    }
    block.tenFormatD = roundHalfAway(value);
    return 0;
  }
  return std::nullopt;
}

mbrt_status readWord(mbrt_ctx& ctx, const mbrt_word& word, NcBlock& block) {
  const char letter = word.letter;
  if (block.nonModal != 0) { // most blocks have no one-shot code
    if (const std::optional<mbrt_status> status =
            readOneShotWord(ctx, word, block)) {
      return *status;
    }
  }
  if (letter == 'K' && ctx.machine.modal.cycle != 0) {
    block.k = roundHalfAway(numeric(word.value));
    return 0;
  }
  if (const int axis = ctx.movedAxisOf(letter); axis >= 0) {
    // X after U in one block: the last of the two counts.
    const std::uint32_t bit = std::uint32_t{1} << axis;
    block.motion.axisMask |= bit;
    block.motion.incrementalMask = ctx.axisOf(letter) >= 0
                                       ? block.motion.incrementalMask & ~bit
                                       : block.motion.incrementalMask | bit;
    return toCounts(ctx, word, addressCountsPerUnit(ctx, letter),
                    ctx.axisCountsPerIncrement(axis), &block.motion.axis[axis]);
  }
  if (letter == 'H' && ctx.profile.lathe()) {
    // A lathe has no H offset: H is only ever the incremental C.
    return raise(ctx, AlarmId::ImproperNcAddress,
                 ctx.profile.gCodeSystem != 'A'
                     ? fmt::format("H is not an address of this machine (the "
                                   "incremental C of G code system A; in "
                                   "system {} write G91 C)",
                                   ctx.profile.gCodeSystem)
                     : std::string("H is not an address of this machine (the "
                                   "incremental C of G code system A, and the "
                                   "profile has no C axis)"));
  }
  if (letter == 'R') {
    block.motion.hasR = true;
    return toLengthCounts(ctx, word, &block.motion.r);
  }
  if (letter == 'C' && chamferByC(ctx)) {
    block.motion.hasC = true;
    return toLengthCounts(ctx, word, &block.motion.c);
  }
  if (letter == 'A' && angleByA(ctx) && block.nonModal == 0) {
    // 3405#4 CCR: the angle of direct drawing dimensions without comma.
    mbrt_word angle = word;
    angle.letter = commaWordLetter('A');
    return readCommaWord(ctx, angle, block.motion);
  }
  if (isArcCenterLetter(letter)) {
    const int index = letter - 'I';
    block.motion.centerMask |= std::uint32_t{1} << index;
    return toLengthCounts(ctx, word, &block.motion.center[index]);
  }
  if (numeric(word.value) < 0.0 &&
      (letter == 'F' || isWholeNumberAddress(letter))) {
    return raise(ctx, AlarmId::IllegalMinusSign,
                 fmt::format("{}{}: {} takes no sign", letter,
                             numeric(word.value), letter));
  }
  if (letter == 'F') {
    ctx.machine.feedInBlock = true;
    ctx.machine.modal.feed = numeric(word.value);
    ctx.machine.lastWords[lastWordSlot(LastWord::F)] = ctx.machine.modal.feed;
    return 0;
  }
  if (letter == 'Q') {
    block.q.emplace();
    return toLengthCounts(ctx, word, &*block.q);
  }
  const int index = lastWordIndex(letter);
  if (index < 0 && isCommaWord(letter)) { // no address of the A..Z tables
    return readCommaWord(ctx, word, block.motion);
  }
  if (index < 0) {
    // U and W are the incremental X and Z of a lathe in G code system A.
    const bool latheAddress = letter == 'U' || letter == 'W';
    if (letter == 'A' && block.nonModal == kLatheOwnCode + 760) {
      return raise(ctx, AlarmId::ImproperNcAddress,
                   "A is not an address of this machine (G76 X Z I K D F "
                   "A P is the Series 10/11 format: parameter 0001#1 FCV)");
    }
    return raise(
        ctx, AlarmId::ImproperNcAddress,
        !latheAddress
            ? fmt::format("{} is not an address of this machine", letter)
        : ctx.profile.lathe()
            ? fmt::format("{} is not an address of this machine (the "
                          "incremental {} of G code system A; in system "
                          "{} write G91 {})",
                          letter, letter == 'U' ? 'X' : 'Z',
                          ctx.profile.gCodeSystem, letter == 'U' ? 'X' : 'Z')
            : fmt::format("{} is not an address of this machine (on "
                          "a lathe {} is the incremental {}: give the "
                          "profile \"series\": \"T\")",
                          letter, letter, letter == 'U' ? 'X' : 'Z'));
  }
  if (word.kind == MBRT_WORD_DEC_LITERAL && isWholeNumberAddress(letter)) {
    // M3.0 is no M code (spec §1.5); a value, M[3.0] or M#1, is rounded.
    return raise(ctx, AlarmId::IllegalDecimalPoint,
                 fmt::format("{}: {} takes a whole number",
                             pointedWordText(letter, numeric(word.value)),
                             letter));
  }
  const double value = roundHalfAway(numeric(word.value));
  if (value > kMaxCodeValue) {
    return raise(ctx, AlarmId::TooManyDigits,
                 fmt::format("{}{}: at most 8 digits", letter, value));
  }
  if (letter == 'S' && block.frames.code == 920 && ctx.profile.lathe()) {
    ctx.machine.spindleLimit = value; // G50 S: not a spindle speed
    return 0;
  }
  ctx.machine.lastWords[index] = value;
  switch (letter) {
    case 'M':
      return readMCode(ctx, value, block.codes);
    case 'T':
      block.codes.t = value;
      return 0;
    case 'S':
      block.codes.s = value;
      return 0;
    case 'B':
      block.codes.b = value;
      return 0;
    default:
      return 0;
  }
}

/// M98 P L. With 8-digit program numbers P is the program and L the repeat
/// count; with 4 digits a P of more than four digits and no L carries the
/// repeat count in its high digits (spec §5.8). Q starts the program at that
/// sequence number; without P it is one of the running program.
mbrt_status callSubprogram(mbrt_ctx& ctx, const NcBlock& block,
                           mbrt_flow* flow) {
  if (!block.hasP && !block.qWritten) {
    return raise(ctx, AlarmId::ProgramNotFound, "M98 without P or Q");
  }
  double program = block.hasP ? block.p : ctx.programNumber();
  if (!block.hasP && program == 0) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("M98 Q{} in a program without an O number",
                             *block.qWritten));
  }
  double repeat = block.hasL ? block.l : 1.0;
  constexpr double kRepeatUnit = kMaxProgramNumber4Digits + 1.0;
  if (ctx.profile.programNumberDigits == 4 && block.hasP && !block.hasL &&
      program > kMaxProgramNumber4Digits && !isNamedProgramNumber(program)) {
    repeat = std::floor(program / kRepeatUnit);
    program = std::fmod(program, kRepeatUnit);
  }
  if (const mbrt_status status = checkProgramNumber(ctx, program)) {
    return status;
  }
  if (block.qWritten && !isSequenceNumber(roundHalfAway(*block.qWritten))) {
    return mbrt_raise_start_sequence(&ctx, *block.qWritten, ctx.programName());
  }
  if (repeat < 1.0) {
    return 0; // L0: no call
  }
  const std::optional<int> number = calledProgramNumber(program);
  if (!number) {
    return raise(ctx, AlarmId::ProgramNotFound,
                 fmt::format("M98 P{}", program));
  }
  flow->kind = MBRT_FLOW_CALL;
  flow->call_kind = MBRT_CALL_SUB;
  flow->program = *number;
  flow->repeat = static_cast<long>(repeat);
  flow->start_seq = block.qWritten ? roundHalfAway(*block.qWritten) : 0.0;
  return 0;
}

mbrt_status decideFlow(mbrt_ctx& ctx, const NcBlock& block, mbrt_flow* flow) {
  for (int i = 0; i < block.codes.mCount; ++i) {
    switch (block.codes.m[i]) {
      case 0:
      case 1:
        ++ctx.run.optionalStops;
        sendMessage(ctx, block.codes.m[i] == 0
                             ? "M00 program stop (the run goes on)"
                             : "M01 optional stop (the run goes on)");
        break;
      case 2:
      case 30:
        flow->kind = MBRT_FLOW_END;
        flow->counts_part = 1;
        break;
      case 98:
      case 198: // from an external device: the program search path
        if (const mbrt_status status = callSubprogram(ctx, block, flow)) {
          return status;
        }
        break;
      case 99:
        flow->kind = MBRT_FLOW_RETURN;
        flow->has_seq = block.hasP;
        flow->seq = block.p;
        break;
      default:
        break;
    }
  }
  return 0;
}

/// G00..G03 motion, when the block has any.
mbrt_status executeBlockMotion(mbrt_ctx& ctx, const MotionWords& motion) {
  const bool arcMode =
      ctx.machine.modal.motion == 2 || ctx.machine.modal.motion == 3;
  // An arc block may leave out the end point: a full circle (I J K) or, with
  // R, no motion at all.
  if (motion.axisMask != 0 ||
      (arcMode && (motion.centerMask != 0 || motion.hasR)) ||
      hasCommaWords(motion)) {
    return executeMotion(ctx, motion);
  }
  return 0;
}

/// Lathe blocks that a mill would run silently wrong: G50 X Z (coordinate
/// setting) or G50 S (spindle speed limit) would be a scaling cancel and a
/// move, G99 F0.25 (feed per revolution) the canned cycle's R level and a
/// crawl of a feed per minute. Until there is a lathe profile they stop the
/// run. A G99 block with a mill's feed (F150.) is no lathe block. Only
/// blocks with G codes can be these.
mbrt_status refuseLatheForms(mbrt_ctx& ctx, const NcBlock& block,
                             const mbrt_word* words, size_t count) {
  if (block.frames.cancelScaling &&
      (block.motion.axisMask != 0 || block.codes.s)) {
    return raise(ctx, AlarmId::Unsupported,
                 "G50 with axis words or S: a lathe's coordinate system "
                 "setting or spindle speed limit (on a mill G50 cancels "
                 "scaling); a lathe profile has \"series\": \"T\"");
  }
  const auto isG99 = [](const mbrt_word& w) {
    return w.letter == 'G' && gWordTenths(w.value) == 990.0;
  };
  constexpr double kLatheFeed[2] = {10.0, 0.4}; // mm, inch per revolution
  if (ctx.machine.modal.returnToR && ctx.machine.modal.cycle == 0 &&
      ctx.machine.feedInBlock &&
      ctx.machine.modal.feed < kLatheFeed[ctx.machine.modal.inch] &&
      std::any_of(words, words + count, isG99)) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("G99 F{}: a lathe's feed per revolution (on a "
                             "mill G99 is the canned cycle's R level and F "
                             "is per minute; G95 feeds per revolution); "
                             "a lathe profile has \"series\": \"T\"",
                             ctx.machine.modal.feed));
  }
  return 0;
}

/// What a block cannot do under cutter compensation: G31 (PS0035), and
/// what mbc does not model yet (MBC0001).
mbrt_status checkUnderCompensation(mbrt_ctx& ctx, const NcBlock& block) {
  if (block.nonModal == 310) {
    return raise(ctx, AlarmId::SkipInCrc,
                 "G31 skip in cutter compensation mode (G41/G42)");
  }
  if (ctx.machine.modal.cycle != 0) {
    return refuseUnderCompensation(
        ctx, fmt::format("canned cycle G{}", ctx.machine.modal.cycle));
  }
  if (ctx.compensation->codeInBlock && ctx.compensation->engaged &&
      ctx.machine.modal.compensation != 40 && block.motion.centerMask != 0 &&
      (ctx.machine.modal.motion <= 1 ||
       ctx.machine.modal.motion == kThreadingMotion ||
       ctx.machine.modal.motion == kVariableLeadMotion)) {
    return refuseUnderCompensation(
        ctx, fmt::format("G{} with I, J or K in offset mode (a vector "
                         "direction)",
                         ctx.machine.modal.compensation));
  }
  return 0;
}

/// What the block's axis words do: dwell, G28, G53, a canned cycle or a
/// move in the modal motion mode.
mbrt_status executeMotionWords(mbrt_ctx& ctx, NcBlock& block) {
  const MotionWords& motion = block.motion;
  // After a chamfer or corner R only a G01 may come: a cycle, dwell or
  // reference return would run before the alarm (lathe_corners.h).
  if (ctx.corner->pending &&
      (block.nonModal != 0 || ctx.machine.modal.cycle != 0)) {
    ctx.corner->pending = false;
    return raise(ctx, AlarmId::NotG01AfterCorner,
                 fmt::format("the block after a chamfer or corner R (line "
                             "{}) must be G01",
                             ctx.corner->line));
  }
  if (hasCommaWords(motion) &&
      (block.nonModal != 0 || ctx.machine.modal.cycle != 0)) {
    return raise(ctx, AlarmId::TooManyAddressCommands,
                 "a chamfer, corner R or ,A belongs to a G00-G03 move, not to "
                 "a cycle, a dwell or a reference return");
  }
  if (block.nonModal >= kLatheOwnCode + 700 &&
      block.nonModal <= kLatheOwnCode + 730) {
    return startShapeCycle(ctx, block.nonModal, block.frames);
  }
  if (block.nonModal >= kLatheOwnCode) {
    return executeRepetitiveCycle(
        ctx, block.nonModal,
        {&motion, block.incrementQ,
         block.hasP ? std::optional<double>(block.p) : std::nullopt,
         std::nullopt, block.tenFormatA, block.tenFormatD});
  }
  if (isLookAheadCode(block.nonModal)) {
    return switchLookAhead(
        ctx, block.nonModal,
        {block.hasP ? std::optional<double>(block.p) : std::nullopt,
         block.qWritten});
  }
  if (block.nonModal == 40) {
    const double seconds = block.hasP ? block.p / 1000.0 : block.dwellSeconds;
    if (seconds < 0.0) {
      return raise(ctx, AlarmId::IllegalMinusSign,
                   fmt::format("G04 dwell of {} s", seconds));
    }
    dwell(ctx, seconds);
    return 0;
  }
  // G53 positions in machine coordinates whatever G16 says; the
  // intermediate point of G28, G29 and G30 in polar coordinates is not
  // modelled yet.
  if (ctx.machine.modal.polar && block.nonModal != 530) {
    if ((block.nonModal == 280 || block.nonModal == 290 ||
         block.nonModal == 300) &&
        writesPlaneWords(ctx, motion)) {
      return raise(ctx, AlarmId::Unsupported,
                   fmt::format("{} with plane axis words in polar coordinate "
                               "mode (G16); give the point after G15",
                               gCodeText(block.nonModal)));
    }
    polarToCartesian(ctx, block.motion);
  }
  if (compensating(ctx)) {
    if (const mbrt_status status = checkUnderCompensation(ctx, block)) {
      return status;
    }
  }
  if (block.nonModal == 390) {
    return cornerArc(ctx, motion);
  }
  if (block.nonModal == 280) {
    return returnToReference(ctx, motion, 1);
  }
  if (block.nonModal == 300) {
    const double reference = block.hasP ? block.p : 2.0;
    if (reference < 2.0 || reference > 4.0) {
      return raise(ctx, AlarmId::IllegalReferenceReturn,
                   fmt::format("G30 P{}: P must be 2, 3 or 4", reference));
    }
    return returnToReference(ctx, motion, static_cast<int>(reference));
  }
  if (block.nonModal == 290) {
    return returnFromReference(ctx, motion);
  }
  if (block.nonModal == 310) { // G31 P1-P4: the multi-step skip's signal
    return motion.axisMask != 0
               ? skipMove(ctx, motion, block.hasP ? block.p : 1.0)
               : 0;
  }
  if (block.nonModal == 530) {
    return moveInMachineCoordinates(ctx, motion);
  }
  if (ctx.machine.modal.cycle != 0) {
    if (!block.k && block.hasL) {
      block.k = block.l; // the older controls' L
    }
    if (block.hasP && block.p < 0.0) {
      return raise(ctx, AlarmId::IllegalMinusSign,
                   fmt::format("cycle dwell P{}", block.p));
    }
    const CycleWords cycle{&motion,
                           block.q,
                           block.hasP ? std::optional<double>(block.p)
                                      : std::nullopt,
                           block.k,
                           std::nullopt,
                           std::nullopt};
    return executeCycleBlock(ctx, cycle);
  }
  return executeBlockMotion(ctx, motion);
}

/// P, L, Q, H and what kind of G codes the block holds, before anything
/// executes.
void scanWords(const mbrt_ctx& ctx, const mbrt_word* words, size_t count,
               NcBlock& block) {
  for (size_t i = 0; i < count; ++i) {
    const char letter = words[i].letter;
    if (letter == 'P' || letter == 'L') {
      const double value = roundHalfAway(numeric(words[i].value));
      (letter == 'P' ? block.hasP : block.hasL) = true;
      (letter == 'P' ? block.p : block.l) = value;
      if (words[i].kind == MBRT_WORD_DEC_LITERAL &&
          block.countWithPoint == nullptr) {
        block.countWithPoint = &words[i];
      }
    } else if (letter == 'Q') {
      block.qWritten = numeric(words[i].value);
      block.incrementQ = static_cast<Counts>(
          words[i].kind == MBRT_WORD_DEC_LITERAL
              ? roundToLengthCounts(ctx, *block.qWritten)
              : roundHalfAway(*block.qWritten) * ctx.countsPerIncrement());
    } else if (letter == 'H' && !ctx.profile.lathe()) {
      block.frames.hasH = true;
    } else if (letter == 'G') {
      noteGCode(ctx, words[i], block);
    }
  }
}

/// P and L are numbers (programs, offsets, sequence numbers), counts and
/// milliseconds: written with a decimal point they are PS0007, as the
/// manual lists the addresses that take one (docs/language.md). G51's P is
/// a magnification and takes one; a value from a variable is rounded.
mbrt_status refuseCountWithPoint(mbrt_ctx& ctx, const NcBlock& block) {
  const mbrt_word& word = *block.countWithPoint;
  if (word.letter == 'P' && block.frames.code == 510) {
    return 0;
  }
  return raise(
      ctx, AlarmId::IllegalDecimalPoint,
      fmt::format("{}: {} takes a whole number{}",
                  pointedWordText(word.letter, numeric(word.value)),
                  word.letter,
                  block.nonModal == 40 && word.letter == 'P'
                      ? " (G04 P counts milliseconds; G04 X1.5 is seconds)"
                      : ""));
}

/// The executed block in the flattened program, its cycle words read as
/// its cycle reads them.
void flattenExecuted(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                     const mbrt_flow& flow, const NcBlock& block) {
  const int code = block.nonModal;
  flattenBlock(ctx, words, count, flow,
               code >= kLatheOwnCode + 740   ? LatheCycleWords::Increments
               : code >= kLatheOwnCode + 700 ? LatheCycleWords::AsWritten
                                             : LatheCycleWords::None);
}

mbrt_status executeWords(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                         mbrt_flow* flow, NcBlock& block) {
  scanWords(ctx, words, count, block);
  ctx.machine.feedInBlock = false;
  ctx.compensation->codeInBlock = false;
  ctx.stack.callingCode = {'\0', 0.0};
  block.frames.axes = &block.motion;
  block.frames.words = words;
  block.frames.count = count;
  // G66, G66.1 and G67 make a block GCodes::Other, and nothing else calls
  // instead of a block unless a modal call or a code call is set up.
  const bool mayCall = block.gCodes == GCodes::Other ||
                       !ctx.stack.modalCalls.empty() || ctx.profile.codeCalls;
  bool taken = false;
  if (const mbrt_status status =
          mayCall ? callInsteadOfBlock(ctx, words, count, flow, &taken) : 0;
      status != 0 || taken) {
    return status;
  }
  if (const mbrt_status status = applyGCodes(ctx, words, count, block)) {
    return status;
  }
  if (block.countWithPoint != nullptr) {
    if (const mbrt_status status = refuseCountWithPoint(ctx, block)) {
      return status;
    }
  }
  // A lathe's G10 reads its own words (U adds, C is the nose radius).
  for (size_t i = 0; i < count && block.frames.code != kLatheG10; ++i) {
    const char letter = words[i].letter;
    if (letter == 'G' || letter == 'P' || letter == 'L') {
      continue;
    }
    if (const mbrt_status status = readWord(ctx, words[i], block)) {
      return status;
    }
  }
  if (ctx.run.readingShape()) {
    readShapeWords(ctx, block.motion.axisMask);
  }
  // Lathe forms need a G code (G50, G99): most blocks have none.
  if (const mbrt_status status =
          block.gCodes != GCodes::None && !ctx.profile.lathe()
              ? refuseLatheForms(ctx, block, words, count)
              : 0) {
    return status;
  }
  bool lengthChanged = false;
  if (const mbrt_status status =
          executeFrameCodes(ctx, block.frames, &lengthChanged)) {
    return status;
  }
  // A lathe's T code selects offsets, unless it calls O9000 (6001#5 TCS).
  if (block.codes.t && ctx.profile.lathe() &&
      !ctx.profile.parameterBit(6001, 5)) {
    bool wearChanged = false;
    if (const mbrt_status status =
            selectLatheOffset(ctx, *block.codes.t, &wearChanged)) {
      return status;
    }
    lengthChanged = lengthChanged || wearChanged;
  }
  const std::uint64_t movesBefore = ctx.machine.moves;
  const std::uint64_t planeMovesBefore = ctx.compensation->planeMoves;
  // The axis words of G52, G92, G51, G51.1, G50.1 and G68 are their data.
  if (block.frames.code == 0) {
    if (const mbrt_status status = executeMotionWords(ctx, block)) {
      return status;
    }
  }
  if (compensating(ctx)) {
    if (const mbrt_status status = compensateBlockEnd(ctx, planeMovesBefore)) {
      return status;
    }
  }
  if (ctx.corner->pending) {
    if (const mbrt_status status = checkCornerTaken(ctx)) {
      return status;
    }
  }
  // Under compensation a move may be held: the block's axis words say
  // whether it moved.
  if (lengthChanged && (compensating(ctx) ? block.motion.axisMask == 0
                                          : ctx.machine.moves == movesBefore)) {
    if (const mbrt_status status = moveToFrame(ctx)) {
      return status;
    }
  }
  if (const mbrt_status status = decideFlow(ctx, block, flow)) {
    return status;
  }
  block.codes.moved = block.motion.axisMask != 0 && block.frames.code == 0 &&
                      !isLookAheadCode(block.nonModal);
  // A block whose calls alarm still moved: it goes to the flattened program.
  // Most runs neither call codes nor flatten: no calls to say so.
  const mbrt_status status =
      ctx.profile.codeCalls || !ctx.stack.modalCalls.empty()
          ? callAfterBlock(ctx, block.codes, flow)
          : 0;
  // A G10 L52 block is flattened with each parameter it lets a block set.
  if (ctx.host.gcodeSink.fn != nullptr && !ctx.run.parameterInput) {
    flattenExecuted(ctx, words, count, *flow, block);
    block.flattened = true;
  }
  return status;
}

mbrt_status executeBlock(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                         mbrt_flow* flow) {
  NcBlock block;
  const std::uint64_t movesBefore = ctx.machine.moves;
  const mbrt_status status = executeWords(ctx, words, count, flow, block);
  // A block that moved before its alarm (a G70 along a shape the tool
  // cannot follow) is in the flattened program too: read back, it moves
  // and alarms alike.
  if (status != 0 && ctx.machine.moves != movesBefore && !block.flattened &&
      ctx.host.gcodeSink.fn != nullptr) {
    flattenExecuted(ctx, words, count, *flow, block);
  }
  return status;
}

} // namespace

} // namespace mbc::rt

using namespace mbc::rt;

mbrt_status mbrt_nc_block(mbrt_ctx* ctx, const mbrt_word* words, size_t count,
                          mbrt_flow* flow) {
  *flow = mbrt_flow{};
  if (ctx->run.parameterInput) {
    if (ctx->host.traceSink.fn != nullptr && count > 0) {
      mbrt_trace_words(ctx, "", words, count);
    }
    return parameterInputBlock(*ctx, words, count);
  }
  // The N number comes first: it only sets #4114, and a block of nothing
  // else does nothing more (it is no block G66.1 calls for, nor traced).
  std::optional<double> sequence;
  ctx->run.blockSequence = -1.0;
  if (count > 0 && words[0].letter == 'N') {
    sequence = mbc::numeric(words[0].value);
    ctx->run.blockSequence = *sequence;
    ctx->machine.lastWords[lastWordSlot(LastWord::N)] = *sequence;
    ++words;
    --count;
  }
  // A lathe's shape cycle reads the blocks of its shape program as they
  // run (lathe_shapes.h).
  const bool shape = ctx->run.readingShape();
  if (count == 0 && !shape) {
    return 0;
  }
  if (ctx->host.traceSink.fn != nullptr && count > 0) {
    mbrt_trace_words(ctx, "", words, count);
  }
  mbrt_status status = shape ? enterShapeBlock(*ctx, sequence) : 0;
  if (status == 0 && count > 0) {
    status = executeBlock(*ctx, words, count, flow);
  }
  if (shape) {
    status = leaveShapeBlock(*ctx, sequence, *flow, status);
  }
  if (status != 0) {
    *flow = mbrt_flow{};
  }
  return status;
}

double mbrt_address_increment(const mbrt_ctx* ctx, char letter) {
  return 1.0 / addressCountsPerUnit(*ctx, letter);
}
