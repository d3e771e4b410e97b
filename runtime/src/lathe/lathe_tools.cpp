// A lathe's T codes and G10 offsets (lathe_tools.h).
#include "lathe_tools.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include "frames.h"
#include "held_block.h"

namespace mbc::rt {

namespace {

constexpr double kOffsetDigits = 100.0; // Ttt oo: two offset digits
constexpr double kGeometryP = 10000.0;  // G10 P10000+n: geometry n

/// An offset's X, Y and Z values in axis counts (X a diameter).
AxisCounts offsetCounts(const mbrt_ctx& ctx, double x, double y, double z) {
  AxisCounts counts{};
  const auto put = [&](char letter, double value) {
    if (const int axis = ctx.axisOf(letter); axis >= 0) {
      counts[axis] = static_cast<Counts>(roundToAxisCounts(ctx, axis, value));
    }
  };
  put('X', x);
  put('Y', y);
  put('Z', z);
  return counts;
}

} // namespace

mbrt_status selectLatheOffset(mbrt_ctx& ctx, double t, bool* moved) {
  const double number = std::fmod(t, kOffsetDigits);
  if (number > ctx.profile.toolOffsetCount) {
    return raise(ctx, AlarmId::IllegalOffsetNumber,
                 fmt::format("T{}: offset {} (the machine has {})", t, number,
                             ctx.profile.toolOffsetCount));
  }
  Frames& frames = ctx.machine.frames;
  const AxisCounts wearBefore = frames.toolWear;
  if (number == 0.0) {
    frames.toolWearNumber = 0;
    frames.toolWear = AxisCounts{};
  } else {
    const LatheOffset& offset =
        ctx.data.latheOffsets[static_cast<std::size_t>(number)];
    const AxisCounts geometry =
        offsetCounts(ctx, offset.xGeometry, offset.yGeometry, offset.zGeometry);
    const bool newGeometry = geometry != frames.toolGeometry;
    if (newGeometry) {
      // The geometry offset moves the coordinate system, which a held
      // move's corner or offset vector cannot span.
      if (const mbrt_status status = refuseUnderHeldMoves(
              ctx, fmt::format("T{} (another geometry offset: a new "
                               "coordinate system)",
                               t))) {
        return status;
      }
    }
    frames.toolWearNumber = static_cast<int>(number);
    frames.toolGeometryNumber = static_cast<int>(number);
    frames.toolGeometry = geometry;
    if (newGeometry) {
      // The tool stays: the program position moves with the system.
      resyncProgram(ctx);
    }
    frames.toolWear =
        offsetCounts(ctx, offset.xWear, offset.yWear, offset.zWear);
  }
  *moved = frames.toolWear != wearBefore;
  return 0;
}

namespace {

/// A G10 word's value: a literal without decimal point counts increments.
double wordUnits(const mbrt_ctx& ctx, const mbrt_word& word, char axis) {
  const int index = ctx.axisOf(axis);
  const double increments =
      index >= 0 ? ctx.axisIncrements(index) : ctx.inputScale();
  const double value = numeric(word.value);
  return word.kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
             ? value / increments
             : roundToCounts(value, increments) / increments;
}

/// The offset field a G10 letter sets (X Y Z R) or adds to (U V W C).
double LatheOffset::*fieldOf(char letter, bool geometry, bool* adds) {
  *adds = letter == 'U' || letter == 'V' || letter == 'W' || letter == 'C';
  switch (letter) {
    case 'X':
    case 'U':
      return geometry ? &LatheOffset::xGeometry : &LatheOffset::xWear;
    case 'Y':
    case 'V':
      return geometry ? &LatheOffset::yGeometry : &LatheOffset::yWear;
    case 'Z':
    case 'W':
      return geometry ? &LatheOffset::zGeometry : &LatheOffset::zWear;
    case 'R':
    case 'C':
      return geometry ? &LatheOffset::rGeometry : &LatheOffset::rWear;
    default:
      return nullptr;
  }
}

char axisOfLetter(char letter) {
  switch (letter) {
    case 'X':
    case 'U':
      return 'X';
    case 'Y':
    case 'V':
      return 'Y';
    case 'Z':
    case 'W':
      return 'Z';
    default:
      return '\0';
  }
}

} // namespace

mbrt_status writeLatheOffsets(mbrt_ctx& ctx, const FrameWords& words) {
  const mbrt_word* pWord = words.word('P');
  const double p = pWord != nullptr ? roundHalfAway(numeric(pWord->value)) : -1;
  const bool geometry = p > kGeometryP;
  const double number = geometry ? p - kGeometryP : p;
  if (p == 0.0) {
    return raise(ctx, AlarmId::Unsupported,
                 "G10 P0 (the workpiece coordinate system shift)");
  }
  if (number < 1.0 || number > ctx.profile.toolOffsetCount ||
      (geometry && !ctx.profile.geometryWear)) {
    return raise(ctx, AlarmId::IllegalPInG10,
                 fmt::format("G10 P{}: P must be 1 to {} (wear){}", p,
                             ctx.profile.toolOffsetCount,
                             ctx.profile.geometryWear
                                 ? " or 10001 and up (geometry)"
                                 : ""));
  }
  LatheOffset& offset = ctx.data.latheOffsets[static_cast<std::size_t>(number)];
  for (std::size_t i = 0; i < words.count; ++i) {
    const mbrt_word& word = words.words[i];
    if (word.letter == 'Q') {
      const double tip = roundHalfAway(numeric(word.value));
      if (tip < 0.0 || tip > 9.0) {
        return raise(ctx, AlarmId::IllegalPInG10,
                     fmt::format("G10 Q{}: the tip direction is 0 to 9", tip));
      }
      offset.tip = tip;
      continue;
    }
    bool adds = false;
    double LatheOffset::*field = fieldOf(word.letter, geometry, &adds);
    if (field == nullptr) {
      continue; // G, P
    }
    const double value = wordUnits(ctx, word, axisOfLetter(word.letter));
    offset.*field = adds ? offset.*field + value : value;
  }
  return 0;
}

} // namespace mbc::rt
