// Words print so that they read back the same. Coordinates (axes, I J K
// R Q) print rounded to the least increment, as the block used them, with
// a decimal point; other words print a literal without decimal point as an
// integer and any other value with a decimal point and as many digits as
// it takes to round-trip (never in exponent form). In G04, G51 and G68
// blocks the coordinate letters mean time, factors and angles, and in
// G05.1 a switch and the axes it names: they print the second way.
#include "flat_gcode.h"

#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/toolpath_json.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "g_codes.h"

namespace mbc::rt {

namespace {

/// The shortest fixed-point text of `value` that parses back to it.
std::string fixedText(double value) {
  std::string text;
  for (int digits = 0; digits <= 20; ++digits) {
    text = fmt::format("{:.{}f}", value, digits);
    if (std::strtod(text.c_str(), nullptr) == value) {
      break;
    }
  }
  return text;
}

/// K is the repeat count of a canned cycle.
bool isCoordinateLetter(const mbrt_ctx& ctx, char letter) {
  return ctx.axisOf(letter) >= 0 || letter == 'I' || letter == 'J' ||
         (letter == 'K' && ctx.modal.cycle == 0) || letter == 'R' ||
         letter == 'Q';
}

/// "12.5", "12.": a coordinate that reads as one under any 3401#0 DPI.
std::string unitsText(double value, int decimals) {
  std::string text = trimmedFixed(value, decimals);
  return text.find('.') == std::string::npos ? text + '.' : text;
}

/// A rotary axis counts 0.001 degree whatever G20/G21.
int axisDecimals(const mbrt_ctx& ctx, int axis) {
  return axis >= 0 && ctx.isRotary(axis) ? 3 : ctx.decimals();
}

std::string coordinateText(const mbrt_ctx& ctx, const mbrt_word& word) {
  const int axis = ctx.axisOf(word.letter);
  const double scale = axis >= 0 ? ctx.axisScale(axis) : ctx.scale();
  const double value = numeric(word.value);
  const double counts =
      word.kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
          ? value
          : roundToCounts(value, scale);
  return fmt::format("{}{}", word.letter,
                     unitsText(counts / scale, axisDecimals(ctx, axis)));
}

/// G04, G51, G68 and the look-ahead switches: blocks whose coordinate
/// letters are no coordinates.
bool hasOtherMeanings(const mbrt_word* words, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter == 'G') {
      const double tenths = std::round(numeric(words[i].value) * 10.0);
      if (tenths == 40.0 || tenths == 510.0 || tenths == 680.0 ||
          isLookAheadCode(static_cast<int>(tenths))) {
        return true;
      }
    }
  }
  return false;
}

std::string wordText(const mbrt_word& word) {
  const double value = numeric(word.value);
  if (isWholeNumberAddress(word.letter)) {
    // The whole number the block used: M3. would be PS0007.
    return fmt::format("{}{}", word.letter,
                       static_cast<long long>(roundHalfAway(value)));
  }
  std::string text = fixedText(value);
  const bool integral = std::floor(value) == value;
  // G54.1 keeps its point; other G codes are whole.
  const bool code = word.letter == 'G';
  if (word.kind != MBRT_WORD_INT_LITERAL && !code &&
      text.find('.') == std::string::npos) {
    text += '.';
  } else if (code && integral) {
    text = fmt::format("{}", static_cast<long long>(value));
  }
  return fmt::format("{}{}", word.letter, text);
}

bool isCode(const mbrt_word& word, char letter, double value) {
  return word.letter == letter && numeric(word.value) == value;
}

/// M98, M198 and M99: the calls and returns the flattened program has run.
bool isTransfer(const mbrt_word& word) {
  return isSubprogramCall(word.letter, numeric(word.value)) ||
         isCode(word, 'M', 99);
}

/// Whether the block hands its P and L to a call or a return.
bool transfers(const mbrt_word* words, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    if (isTransfer(words[i])) {
      return true;
    }
  }
  return false;
}

void send(mbrt_ctx& ctx, const std::string& line) {
  sendText(ctx, ctx.gcodeSink, line);
}

/// G10 writes in G90; a run in G91 goes back to it after.
void sendData(mbrt_ctx& ctx, const std::string& data) {
  send(ctx,
       fmt::format("G90 {}\n{}", data, ctx.modal.incremental ? "G91\n" : ""));
}

} // namespace

void flattenBlock(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                  const mbrt_flow& flow) {
  const bool dropTransfer = transfers(words, count);
  const bool exact = hasOtherMeanings(words, count);
  const auto [callLetter, callValue] = ctx.callingCode;
  const bool codeCall =
      flow.kind == MBRT_FLOW_CALL && (flow.call_kind & kCallCodeBit) != 0;
  std::string line;
  for (size_t i = 0; i < count; ++i) {
    const mbrt_word& word = words[i];
    if (dropTransfer &&
        (isTransfer(word) || word.letter == 'P' || word.letter == 'L')) {
      continue;
    }
    // G67 is a macro statement: the flattened program has no modal calls.
    if ((codeCall && isCode(word, callLetter, callValue)) ||
        isCode(word, 'G', 67)) {
      continue;
    }
    line += line.empty() ? "" : " ";
    line += !exact && isCoordinateLetter(ctx, word.letter)
                ? coordinateText(ctx, word)
                : wordText(word);
  }
  if (!line.empty()) {
    send(ctx, line + "\n");
  }
}

void flattenWorkOffset(mbrt_ctx& ctx, int offset) {
  if (ctx.gcodeSink.fn == nullptr) {
    return;
  }
  std::string data =
      offset < kFirstG541Offset
          ? fmt::format("G10 L2 P{}", offset - kExternalOffset)
          : fmt::format("G10 L20 P{}", offset - kFirstG541Offset + 1);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    data += fmt::format(" {}{}", ctx.profile.axes[axis],
                        unitsText(countsToUnits(ctx.workOffsets[offset][axis],
                                                ctx.axisScale(axis)),
                                  axisDecimals(ctx, axis)));
  }
  sendData(ctx, data);
}

void flattenToolOffset(mbrt_ctx& ctx, int l, int number, double value) {
  if (ctx.gcodeSink.fn == nullptr) {
    return;
  }
  sendData(ctx, fmt::format("G10 L{} P{} R{}", l, number,
                            unitsText(value, ctx.decimals())));
}

void flattenLookAheadStop(mbrt_ctx& ctx, int blocks) {
  if (ctx.gcodeSink.fn == nullptr) {
    return;
  }
  for (int i = 0; i < blocks; ++i) {
    sendData(ctx, "G04 P0");
  }
}

} // namespace mbc::rt
