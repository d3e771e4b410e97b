// G10 L52 ... G11 (parameter_input.h). A program sets the parameters a
// profile may set (docs/machine-profile.md), each checked as the profile's
// are; a parameter mbc does not model stops the run, since setting it
// could change what the control does next in a way mbc would not follow.
// What a program sets lasts until mbrt_reset, as on the control until the
// operator changes it back.
#include "parameter_input.h"

#include <mbc/arith.h>

#include <fmt/format.h>

#include "flat_gcode.h"
#include "lathe_settings.h"
#include "lathe_state.h"
#include "parameters.h"

namespace mbc::rt {

namespace {

constexpr double kParameterInputL = 52; // the 0i-F's and 30i-B's L
constexpr double kFifteenFormatL = 50;  // the same mode, as some manuals write

/// The last word of `letter`, or nullptr.
const mbrt_word* findWord(const mbrt_word* words, size_t count, char letter) {
  const mbrt_word* found = nullptr;
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter == letter) {
      found = &words[i];
    }
  }
  return found;
}

/// Why a program may not change parameter `number` to `value` mid-run, or
/// nullptr: some say what the machine is (its axes, their kind, the G code
/// system), which would need the machine rebuilt under the program; 6004#0
/// NAT holds for a whole run, since compiled code shares the values of
/// ASIN and ATAN between the blocks that compute them.
const char* fixedForTheRun(int number, double value, const Profile& profile) {
  if (number == 1006 || number == 1008 || number == 1260) {
    return "says what the machine is";
  }
  const auto changed = [&](long bits) {
    return ((static_cast<long>(value) ^
             static_cast<long>(profile.parameter(number))) &
            bits) != 0;
  };
  constexpr long kCodeSystemBits = 0xC0; // 3401#6 GSB, #7 GSC
  if (number == 3401 && changed(kCodeSystemBits)) {
    return "says what the machine is (the G code system)";
  }
  if (number == 6004 && changed(1)) {
    return "holds for a whole run (bit 0 NAT: compiled code shares ASIN and "
           "ATAN values)";
  }
  return nullptr;
}

mbrt_status badData(mbrt_ctx& ctx, double number, const std::string& what) {
  return raise(ctx, AlarmId::IllegalExpressionFormat,
               fmt::format("G10 L52 N{}: {}", number, what));
}

} // namespace

bool startsParameterInput(const FrameWords& words) {
  const mbrt_word* l = words.word('L');
  const double value = l != nullptr ? roundHalfAway(numeric(l->value)) : 0.0;
  return value == kParameterInputL || value == kFifteenFormatL;
}

mbrt_status startParameterInput(mbrt_ctx& ctx, const FrameWords&) {
  ctx.run.parameterInput = true;
  return 0;
}

mbrt_status parameterInputBlock(mbrt_ctx& ctx, const mbrt_word* words,
                                size_t count) {
  if (const mbrt_word* g = findWord(words, count, 'G')) {
    if (numeric(g->value) == 11.0) {
      ctx.run.parameterInput = false;
      return 0;
    }
    return raise(ctx, AlarmId::IllegalExpressionFormat,
                 fmt::format("G{} in the parameter input mode (G10 L52): a "
                             "block sets one parameter, N R [P] [Q], until G11",
                             numeric(g->value)));
  }
  const mbrt_word* n = findWord(words, count, 'N');
  const mbrt_word* r = findWord(words, count, 'R');
  if (n == nullptr && r == nullptr) {
    return 0; // a block of nothing, or only a comment
  }
  const double number = n != nullptr ? roundHalfAway(numeric(n->value)) : 0.0;
  if (n == nullptr || r == nullptr) {
    return badData(ctx, number,
                   "a block sets one parameter: N the number, R the value");
  }
  const ParameterSpec* spec = findParameter(static_cast<int>(number));
  const double value = numeric(r->value);
  if (spec == nullptr) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("G10 L52 N{}: parameter {} is not one mbc models "
                             "(docs/machine-profile.md lists them)",
                             number, number));
  }
  Profile& profile = ctx.profile;
  const int parameter = static_cast<int>(number);
  const mbrt_word* p = findWord(words, count, 'P');
  const mbrt_word* q = findWord(words, count, 'Q');
  if (spec->perAxis != (p != nullptr)) {
    return badData(ctx, number,
                   spec->perAxis ? "a per-axis parameter needs P, the axis "
                                   "number"
                                 : "P (an axis number) is for per-axis "
                                   "parameters only");
  }
  double newValue = value;
  if (q != nullptr) {
    const double bit = roundHalfAway(numeric(q->value));
    const bool bitParameter = spec->bits();
    if (!bitParameter || bit < 0.0 || bit > 7.0 || (value != 0 && value != 1)) {
      return badData(ctx, number,
                     "Q is the bit (0-7) of a bit parameter, R its value 0 "
                     "or 1");
    }
    const long mask = 1L << static_cast<int>(bit);
    const auto byte = static_cast<long>(profile.parameter(parameter));
    newValue = static_cast<double>(value != 0 ? byte | mask : byte & ~mask);
  }
  if (const char* why = fixedForTheRun(parameter, newValue, profile)) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("G10 L52 N{}: parameter {} {}; set it in the "
                             "machine profile",
                             number, number, why));
  }
  if (const std::optional<std::string> error =
          parameterValueError(*spec, newValue)) {
    return badData(ctx, number, fmt::format("R{} {}", value, *error));
  }
  if (const std::optional<std::string> error =
          callingCodeError(parameter, newValue)) {
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("G10 L52 N{}: R{} {}", number, value, *error));
  }
  if (spec->perAxis) {
    const double axis = roundHalfAway(numeric(p->value));
    if (axis < 1.0 || axis > ctx.axisCount()) {
      return badData(ctx, number,
                     fmt::format("P{}: the axis number is 1 to {}", axis,
                                 ctx.axisCount()));
    }
    profile.axisParameterValues(parameter)[static_cast<std::size_t>(axis) - 1] =
        newValue;
    flattenParameter(ctx, parameter, static_cast<int>(axis), newValue);
    deriveParameterFields(profile);
    return 0;
  }
  profile.parameters[parameter] = newValue;
  flattenParameter(ctx, parameter, 0, newValue);
  // A cycle's first block keeps its settings in place of 5130-5143; the
  // parameter set now is the newer.
  ctx.lathe->cycleSettings.erase(parameter);
  deriveParameterFields(profile);
  return 0;
}

} // namespace mbc::rt
