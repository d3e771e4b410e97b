// The look-ahead switches (see look_ahead.h).
#include "look_ahead.h"

#include <fmt/format.h>

#include "g_codes.h"

namespace mbc::rt {

namespace {

mbrt_status badSwitch(mbrt_ctx& ctx, int tenths, char letter,
                      const std::optional<double>& value, const char* allowed) {
  return raise(ctx, AlarmId::ImproperNcAddress,
               value ? fmt::format("{} {}{}: {} takes {}", gCodeText(tenths),
                                   letter, *value, letter, allowed)
                     : fmt::format("{} without {}: {} takes {}",
                                   gCodeText(tenths), letter, letter, allowed));
}

} // namespace

mbrt_status switchLookAhead(mbrt_ctx& ctx, int tenths,
                            const LookAheadWords& words) {
  switch (tenths) {
    case kG05:
      // P10000/P0 is AI contour control in the form of the high-precision
      // contour control of older controls; the other P values run binary
      // data of high-speed cycle machining.
      if (words.p == 0.0 || words.p == 10000.0) {
        return 0;
      }
      if (words.p) {
        return raise(
            ctx, AlarmId::Unsupported,
            fmt::format("G05 P{} (high-speed cycle machining)", *words.p));
      }
      return raise(ctx, AlarmId::Unsupported,
                   "G05 without P (high-speed binary program operation)");
    case kG051:
      if (words.q == 0.0 || words.q == 1.0) {
        return 0; // AI contour control off / on: speed, not path
      }
      if (words.q == 2.0 || words.q == 3.0) {
        // Smooth interpolation and nano smoothing fit a curve through the
        // programmed points within a tolerance of the machine's parameters.
        sendMessage(ctx, fmt::format("G05.1 Q{} {}: the toolpath keeps the "
                                     "programmed points (the control smooths "
                                     "between them within its tolerance)",
                                     *words.q,
                                     *words.q == 2.0 ? "smooth interpolation"
                                                     : "nano smoothing"));
        return 0;
      }
      return badSwitch(ctx, tenths, 'Q', words.q, "0, 1, 2 or 3");
    case kG054:
      if (words.q == 0.0 || words.q == 1.0) {
        return 0; // high-speed HRV current control: the servo, not the path
      }
      return badSwitch(ctx, tenths, 'Q', words.q, "0 or 1");
    case kG08:
      if (words.p == 0.0 || words.p == 1.0) {
        return 0; // advanced preview control off / on
      }
      return badSwitch(ctx, tenths, 'P', words.p, "0 or 1");
    default:
      return 0;
  }
}

} // namespace mbc::rt
