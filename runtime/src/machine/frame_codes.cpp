// G52, G92, G51/G50, G51.1/G50.1, G68/G69 and G43/G44/G49. Centres are
// absolute program coordinates whatever G90/G91 says; an axis a centre
// leaves out takes the current position.
#include "frame_codes.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include <numbers>

#include "cutter_comp.h"
#include "data_input.h"
#include "frames.h"
#include "g_codes.h"
#include "held_block.h"
#include "lathe_codes.h"
#include "lathe_tools.h"
#include "parameter_input.h"
#include "tool_moves.h"

namespace mbc::rt {

namespace {

bool has(const MotionWords& axes, int axis) {
  return (axes.axisMask >> axis & 1) != 0;
}

/// The centre of a transform: the axis word, else the current position.
double centerOf(const mbrt_ctx& ctx, const MotionWords& axes, int axis) {
  return static_cast<double>(has(axes, axis) ? axes.axis[axis]
                                             : programPosition(ctx)[axis]);
}

void setLocalOrigin(mbrt_ctx& ctx, const MotionWords& axes) {
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (has(axes, axis)) {
      ctx.machine.frames.local[axis] = axes.axis[axis];
    }
  }
}

/// G92: the control point becomes the commanded position; it replaces the
/// G52 local origin on the axes it names.
mbrt_status setCoordinateSystem(mbrt_ctx& ctx, const MotionWords& axes) {
  if (ctx.machine.frames.transforms()) {
    return raise(ctx, AlarmId::Unsupported,
                 "G92 while G51, G51.1 or G68 is in force");
  }
  const AxisCounts work = machineToWork(ctx, ctx.machine.position);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (has(axes, axis)) {
      ctx.machine.frames.preset[axis] += work[axis] - axes.axis[axis];
      ctx.machine.frames.local[axis] = 0;
    }
  }
  return 0;
}

/// G92.1: the workpiece system without the G92 shift and the local origin
/// on the axes named.
void presetCoordinateSystem(mbrt_ctx& ctx, const MotionWords& axes) {
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (has(axes, axis)) {
      ctx.machine.frames.preset[axis] = 0;
      ctx.machine.frames.local[axis] = 0;
    }
  }
}

void setMirror(mbrt_ctx& ctx, const MotionWords& axes) {
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    if (has(axes, axis)) {
      ctx.machine.frames.mirrorMask |= std::uint32_t{1} << axis;
      ctx.machine.frames.mirrorCenter[axis] =
          static_cast<double>(axes.axis[axis]);
    }
  }
}

/// G50.1 cancels the axes it names, all of them when it names none.
void cancelMirror(mbrt_ctx& ctx, const MotionWords& axes) {
  ctx.machine.frames.mirrorMask =
      axes.axisMask == 0 ? 0 : ctx.machine.frames.mirrorMask & ~axes.axisMask;
}

/// A magnification word: with a decimal point the factor itself, without
/// one a count of 0.00001 (0.001 with parameter 5400#7 SCR).
double magnification(const mbrt_ctx& ctx, const mbrt_word& word) {
  const double value = numeric(word.value);
  if (word.kind != MBRT_WORD_INT_LITERAL) {
    return value;
  }
  return value * (ctx.profile.parameterBit(5400, 7) ? 0.001 : 0.00001);
}

/// G51 X Y Z P (one factor) or, with parameter 5400#6 XSC, I J K (one
/// per axis; a negative one mirrors). X, Y and Z are scaled.
mbrt_status setScaling(mbrt_ctx& ctx, const FrameWords& words) {
  const bool perAxis = ctx.profile.parameterBit(5400, 6);
  const double unit = ctx.profile.parameterBit(5400, 7) ? 0.001 : 0.00001;
  const double limit = 999'999.0 * unit;
  AxisValues scale{};
  scale.fill(1.0);
  AxisValues center{};
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    center[axis] = centerOf(ctx, *words.axes, axis);
  }
  for (int i = 0; i < 3; ++i) {
    const int axis = ctx.axisOf(static_cast<char>('X' + i));
    if (axis < 0) {
      continue;
    }
    const mbrt_word* word = words.word(perAxis ? "IJK"[i] : 'P');
    double factor = word != nullptr ? magnification(ctx, *word) : 0.0;
    if (word == nullptr) {
      const double fallback = ctx.profile.parameter(5411);
      factor = fallback == 0.0 ? 1.0 : fallback * unit;
    }
    if (factor == 0.0 || std::fabs(factor) > limit ||
        (!perAxis && factor < 0)) {
      return raise(ctx, AlarmId::IllegalScaleRate,
                   fmt::format("G51 magnification {}", factor));
    }
    scale[axis] = factor;
  }
  ctx.machine.frames.scaling = true;
  ctx.machine.frames.scale = scale;
  ctx.machine.frames.scaleCenter = center;
  return 0;
}

/// G68 X Y R in the plane of G17/G18/G19; R in degrees (a literal without
/// decimal point in 0.001 degree), incremental in G91 with parameter
/// 5400#0 RIN; without R the angle of parameter 5410.
mbrt_status setRotation(mbrt_ctx& ctx, const FrameWords& words) {
  if (words.word('I') || words.word('J') || words.word('K')) {
    return raise(ctx, AlarmId::Unsupported,
                 "G68 with I, J, K (3-dimensional coordinate conversion)");
  }
  const PlaneAxes plane = planeAxes(ctx.machine.modal.plane);
  const char* letters = plane.letters;
  const int p = ctx.axisOf(letters[0]);
  const int q = ctx.axisOf(letters[1]);
  if (p < 0 || q < 0) {
    return raise(ctx, AlarmId::ImproperNcAddress,
                 fmt::format("G68 in G{} needs axes {} and {}",
                             ctx.machine.modal.plane, letters[0], letters[1]));
  }
  double angle = ctx.profile.parameter(5410) / 1000.0;
  if (const mbrt_word* r = words.word('R')) {
    const bool thousandths =
        r->kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput;
    angle = numeric(r->value) / (thousandths ? 1000.0 : 1.0);
    if (ctx.machine.modal.incremental && ctx.profile.parameterBit(5400, 0) &&
        ctx.machine.frames.rotation) {
      angle += ctx.machine.frames.angle;
    }
  }
  Frames& frames = ctx.machine.frames;
  frames.rotationCenter[0] = centerOf(ctx, *words.axes, p);
  frames.rotationCenter[1] = centerOf(ctx, *words.axes, q);
  frames.rotation = true;
  frames.rotationAxes[0] = p;
  frames.rotationAxes[1] = q;
  frames.angle = angle;
  const double radians = angle * std::numbers::pi / 180.0;
  frames.cosAngle = std::cos(radians);
  frames.sinAngle = std::sin(radians);
  return 0;
}

/// G43/G44 H: the offset (geometry plus wear) of H, on Z (or, with
/// parameter 5001#1 TLB, the axis normal to the plane); H0 is no offset.
mbrt_status setToolLength(mbrt_ctx& ctx, int mode) {
  Frames& frames = ctx.machine.frames;
  if (mode == 49) {
    frames.lengthMode = 49;
    frames.lengthAxis = -1;
    frames.length = 0;
    return 0;
  }
  if (ctx.profile.parameterBit(5001, 0)) {
    return raise(ctx, AlarmId::Unsupported,
                 "tool length compensation C (parameter 5001#0 TLC)");
  }
  static constexpr char kNormals[3] = {'Z', 'Y', 'X'};
  const char letter = ctx.profile.parameterBit(5001, 1)
                          ? kNormals[ctx.machine.modal.plane - 17]
                          : 'Z';
  const int axis = ctx.axisOf(letter);
  if (axis < 0) {
    return raise(
        ctx, AlarmId::ImproperNcAddress,
        fmt::format("G{} offsets {}, which this machine lacks", mode, letter));
  }
  const double h = ctx.machine.lastWords[lastWordSlot(LastWord::H)];
  if (h < 0.0 || h > ctx.profile.toolOffsetCount) {
    return raise(ctx, AlarmId::IllegalOffsetNumber,
                 fmt::format("H{} (the machine has {})", h,
                             ctx.profile.toolOffsetCount));
  }
  const auto number = static_cast<std::size_t>(h);
  const double value = number == 0 ? 0.0
                                   : ctx.data.toolOffsets[number].hGeometry +
                                         ctx.data.toolOffsets[number].hWear;
  const auto counts = static_cast<Counts>(roundToLengthCounts(ctx, value));
  frames.lengthMode = mode;
  frames.lengthAxis = axis;
  frames.length = mode == 44 ? -counts : counts;
  return 0;
}

mbrt_status executeFrameCode(mbrt_ctx& ctx, const FrameWords& words) {
  switch (words.code) {
    case 520:
      setLocalOrigin(ctx, *words.axes);
      return 0;
    case 920:
      return setCoordinateSystem(ctx, *words.axes);
    case 921:
      presetCoordinateSystem(ctx, *words.axes);
      return 0;
    case 510:
      return setScaling(ctx, words);
    case 511:
      setMirror(ctx, *words.axes);
      return 0;
    case 501:
      cancelMirror(ctx, *words.axes);
      return 0;
    case 680:
      return setRotation(ctx, words);
    case 100:
    case kLatheG10:
      if (startsParameterInput(words)) {
        return startParameterInput(ctx, words);
      }
      return words.code == 100 ? programmableDataInput(ctx, words)
                               : writeLatheOffsets(ctx, words);
    default:
      return 0;
  }
}

/// What of a block's frame words mbc does not model under cutter
/// compensation, or "" (G10 offset data is fine).
std::string frameChangeName(const FrameWords& words) {
  if (words.code != 0 && words.code != 100 && words.code != kLatheG10) {
    return gCodeText(words.code);
  }
  if (words.cancelScaling || words.cancelRotation) {
    return words.cancelScaling ? "G50" : "G69";
  }
  return "";
}

} // namespace

mbrt_status applyFrameCodes(mbrt_ctx& ctx, const FrameWords& words,
                            bool* lengthChanged) {
  if (const std::string change = frameChangeName(words); !change.empty()) {
    if (const mbrt_status status = refuseUnderCompensation(ctx, change)) {
      return status;
    }
  }
  const bool frameChanged =
      words.code != 0 || words.cancelScaling || words.cancelRotation;
  ctx.machine.frames.scaling =
      ctx.machine.frames.scaling && !words.cancelScaling;
  ctx.machine.frames.rotation =
      ctx.machine.frames.rotation && !words.cancelRotation;
  if (const mbrt_status status = executeFrameCode(ctx, words)) {
    return status;
  }
  if (frameChanged) {
    resyncProgram(ctx);
  }
  const int mode = words.lengthCode != 0 ? words.lengthCode
                   : words.hasH          ? ctx.machine.frames.lengthMode
                                         : 0;
  if (mode == 0 || (mode == 49 && ctx.machine.frames.lengthMode == 49)) {
    return 0;
  }
  const Frames before = ctx.machine.frames;
  if (const mbrt_status status = setToolLength(ctx, mode)) {
    return status;
  }
  *lengthChanged = before.lengthAxis != ctx.machine.frames.lengthAxis ||
                   before.length != ctx.machine.frames.length;
  // A length offset along an axis of the compensation plane would move
  // the plane's vector too, which the manuals do not show.
  const PlaneIndex plane = planeIndex(ctx);
  const auto inPlane = [&](int axis) {
    return axis >= 0 && (axis == plane.p || axis == plane.q);
  };
  if (*lengthChanged &&
      (inPlane(before.lengthAxis) || inPlane(ctx.machine.frames.lengthAxis))) {
    return refuseUnderCompensation(
        ctx, "a tool length offset along an axis of the compensation plane");
  }
  return 0;
}

} // namespace mbc::rt
