// Words print so that they read back to the same run. Coordinates (axes,
// I J K R Q) print rounded to the least increment, as the block used them,
// with a decimal point. Numbers and counts (M S T H D, P and L but G51's
// P, a canned cycle's K, the sequence numbers of a lathe's shape cycle)
// print as the whole number the block used, rounded from a variable's
// value; G codes as the code that ran (G1.04 ran as G01). Other words
// print a literal without decimal point as an integer and any other value
// with a decimal point and as many digits as it takes to round-trip (never
// in exponent form). In G04, G51 and G68 blocks the coordinate letters
// mean time, factors and angles, and in G05.1 a switch and the axes it
// names: they print the second way.
#include "flat_gcode.h"

#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/number_text.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "g_codes.h"
#include "g_word.h"
#include "machine_unit.h"

namespace mbc::rt {

namespace {

/// The shortest fixed-point text of `value` that parses back to it.
void appendFixedText(std::string& out, double value) {
  // 309 integer digits, the point and 20 decimals at most.
  char text[340];
  std::size_t size = 0;
  for (int digits = 0; digits <= 20; ++digits) {
    size =
        fmt::format_to_n(text, sizeof text - 1, "{:.{}f}", value, digits).size;
    text[size] = '\0';
    if (std::strtod(text, nullptr) == value) {
      break;
    }
  }
  out.append(text, size);
}

/// K is the repeat count of a canned cycle.
bool isCoordinateLetter(const mbrt_ctx& ctx, char letter) {
  return ctx.movedAxisOf(letter) >= 0 || letter == 'I' || letter == 'J' ||
         (letter == 'K' && ctx.machine.modal.cycle == 0) || letter == 'R' ||
         letter == 'Q' || isCommaWord(letter);
}

/// "12.5", "12.": a coordinate that reads as one under any 3401#0 DPI.
void appendUnitsText(std::string& out, double value, int decimals) {
  const std::size_t start = out.size();
  appendTrimmedFixed(out, value, decimals);
  if (out.find('.', start) == std::string::npos) {
    out += '.';
  }
}

/// A rotary axis counts 0.001 degree whatever G20/G21.
int axisDecimals(const mbrt_ctx& ctx, int axis) {
  return axis >= 0 && ctx.isRotary(axis) ? 3 : ctx.decimals();
}

void appendCoordinateText(std::string& out, const mbrt_ctx& ctx,
                          const mbrt_word& word) {
  const int axis = ctx.movedAxisOf(word.letter);
  const double scale = addressCountsPerUnit(ctx, word.letter);
  const double value = numeric(word.value);
  const double counts =
      word.kind == MBRT_WORD_INT_LITERAL && !ctx.profile.decimalPointInput
          ? value
          : roundToCounts(value, scale);
  appendAddressText(out, word.letter);
  appendUnitsText(out, counts / scale, axisDecimals(ctx, axis));
}

/// Whether the block has the G code of `tenths`.
bool hasCode(const mbrt_word* words, size_t count, double tenths) {
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter == 'G' && gWordTenths(words[i].value) == tenths) {
      return true;
    }
  }
  return false;
}

/// G04, G51, G68, the look-ahead switches and a lathe's G10: blocks whose
/// coordinate letters are no coordinates.
bool hasOtherMeanings(const mbrt_ctx& ctx, const mbrt_word* words,
                      size_t count) {
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter == 'G') {
      const double tenths = gWordTenths(words[i].value);
      if (tenths == 40.0 || tenths == 510.0 || tenths == 680.0 ||
          isLookAheadCode(static_cast<int>(tenths)) ||
          (tenths == 100.0 && ctx.profile.lathe())) {
        return true;
      }
    }
  }
  return false;
}

/// Whether the block read `letter` as a whole number: a value with a
/// fraction was rounded, and a decimal point would be PS0007.
bool readsWholeNumber(const mbrt_ctx& ctx, char letter, bool scaling,
                      LatheCycleWords cycle) {
  return isWholeNumberAddress(letter) || letter == 'L' ||
         (letter == 'P' && !scaling) ||
         (letter == 'K' && ctx.machine.modal.cycle != 0) ||
         (letter == 'Q' && cycle == LatheCycleWords::AsWritten);
}

void appendWordText(std::string& out, const mbrt_word& word, bool whole) {
  const double value = numeric(word.value);
  out += word.letter;
  if (whole) {
    appendInteger(out, static_cast<long long>(roundHalfAway(value)));
    return;
  }
  if (word.letter == 'G') {
    // The code that ran, in tenths: G54.1 keeps its point.
    const long long tenths = static_cast<long long>(roundHalfAway(value * 10));
    appendInteger(out, tenths / 10);
    if (tenths % 10 != 0) {
      out += '.';
      appendInteger(out, tenths % 10);
    }
    return;
  }
  const std::size_t start = out.size();
  appendFixedText(out, value);
  if (word.kind != MBRT_WORD_INT_LITERAL &&
      out.find('.', start) == std::string::npos) {
    out += '.';
  }
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
  sendText(ctx, ctx.host.gcodeSink, line);
}

/// G10 writes in G90; a run in G91 goes back to it after. In a lathe's G
/// code system A, G90 is a cycle and X is absolute anyway.
void sendData(mbrt_ctx& ctx, const std::string& data) {
  if (ctx.profile.lathe() && ctx.profile.gCodeSystem == 'A') {
    send(ctx, data + '\n');
    return;
  }
  send(ctx, fmt::format("G90 {}\n{}", data,
                        ctx.machine.modal.incremental ? "G91\n" : ""));
}

} // namespace

void flattenBlock(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                  const mbrt_flow& flow, LatheCycleWords cycle) {
  const bool dropTransfer = transfers(words, count);
  const bool exact = cycle == LatheCycleWords::AsWritten ||
                     hasOtherMeanings(ctx, words, count);
  const bool increments = cycle == LatheCycleWords::Increments;
  const bool scaling = hasCode(words, count, 510.0);
  const auto [callLetter, callValue] = ctx.stack.callingCode;
  const bool codeCall =
      flow.kind == MBRT_FLOW_CALL && (flow.call_kind & kCallCodeBit) != 0;
  std::string& line = ctx.run.gcodeLine;
  line.clear();
  if (ctx.run.blockSequence >= 0.0) {
    line += 'N';
    appendInteger(line, static_cast<long long>(ctx.run.blockSequence));
  }
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
    if (!line.empty()) {
      line += ' ';
    }
    if (increments && (word.letter == 'P' || word.letter == 'Q') &&
        word.kind != MBRT_WORD_DEC_LITERAL) {
      line += word.letter;
      appendInteger(line,
                    static_cast<long long>(roundHalfAway(numeric(word.value))));
    } else if (!exact && isCoordinateLetter(ctx, word.letter)) {
      appendCoordinateText(line, ctx, word);
    } else {
      appendWordText(line, word,
                     readsWholeNumber(ctx, word.letter, scaling, cycle));
    }
  }
  if (!line.empty()) {
    line += '\n';
    send(ctx, line);
  }
}

void flattenProgramStart(mbrt_ctx& ctx) {
  if (ctx.host.gcodeSink.fn == nullptr || ctx.stack.mainProgramNumber <= 0) {
    return;
  }
  send(ctx, fmt::format("O{:04}\n", ctx.stack.mainProgramNumber));
}

void flattenWorkOffset(mbrt_ctx& ctx, int offset) {
  if (ctx.host.gcodeSink.fn == nullptr) {
    return;
  }
  std::string data =
      offset < kFirstG541Offset
          ? fmt::format("G10 L2 P{}", offset - kExternalOffset)
          : fmt::format("G10 L20 P{}", offset - kFirstG541Offset + 1);
  for (int axis = 0; axis < ctx.axisCount(); ++axis) {
    data += ' ';
    data += ctx.profile.axes[axis];
    appendUnitsText(data,
                    countsToUnits(workOffsetInForce(ctx, offset, axis),
                                  ctx.axisScale(axis)),
                    axisDecimals(ctx, axis));
  }
  sendData(ctx, data);
}

void flattenToolOffset(mbrt_ctx& ctx, int l, int number, double value) {
  if (ctx.host.gcodeSink.fn == nullptr) {
    return;
  }
  std::string data = fmt::format("G10 L{} P{} R", l, number);
  appendUnitsText(data, value, ctx.decimals());
  sendData(ctx, data);
}

void flattenLatheOffset(mbrt_ctx& ctx, int p, char letter, double value) {
  if (ctx.host.gcodeSink.fn == nullptr) {
    return;
  }
  std::string data = fmt::format("G10 P{} {}", p, letter);
  if (letter == 'Q') {
    data += fmt::format("{}", value);
  } else {
    appendUnitsText(data, value, ctx.decimals());
  }
  sendData(ctx, data);
}

void flattenParameter(mbrt_ctx& ctx, int number, int axis, double value) {
  if (ctx.host.gcodeSink.fn == nullptr) {
    return;
  }
  send(ctx, fmt::format("G10 L52\nN{}{} R{}\nG11\n", number,
                        axis > 0 ? fmt::format(" P{}", axis) : "", value));
}

void flattenLookAheadStop(mbrt_ctx& ctx, int blocks) {
  if (ctx.host.gcodeSink.fn == nullptr) {
    return;
  }
  for (int i = 0; i < blocks; ++i) {
    sendData(ctx, "G04 P0");
  }
}

} // namespace mbc::rt
