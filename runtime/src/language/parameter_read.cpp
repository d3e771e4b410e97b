// PRM[n], PRM[n, bit], PRM[n]/[axis], PRM[n, bit]/[axis]: a macro reads a
// parameter of the machine (mbc/engine.h). Only the parameters a profile
// may set have values here; reading another would be a guess, so it stops
// the run.
#include <mbc/arith.h>
#include <mbc/engine.h>

#include <fmt/format.h>

#include "context.h"
#include "parameters.h"

namespace mbc::rt {

namespace {

/// A per-axis parameter as the profile set it or, for those the profile
/// derives the machine from, as that derivation reads it.
double axisParameterValue(const Profile& profile, int number, int axis) {
  if (profile.axisParameters.count(number) != 0) {
    return profile.axisParameter(number, axis);
  }
  const std::uint32_t bit = std::uint32_t{1} << axis;
  switch (number) {
    case 1006: // #0 ROT, #3 DIA
      return ((profile.rotaryMask & bit) != 0 ? 1.0 : 0.0) +
             ((profile.diameterMask & bit) != 0 ? 8.0 : 0.0);
    case 1008: // #0 ROA, #1 RAB
      return ((profile.rolloverMask & bit) != 0 ? 1.0 : 0.0) +
             ((profile.bySignMask & bit) != 0 ? 2.0 : 0.0);
    case 1260:
      return (profile.rolloverMask & bit) != 0
                 ? profile.rotationDegrees[static_cast<std::size_t>(axis)]
                 : 360.0;
    default:
      return profile.axisParameter(number, axis);
  }
}

mbrt_status outOfRange(mbrt_ctx& ctx, double number, const std::string& why) {
  return raise(ctx, AlarmId::ArgumentOutOfRange,
               fmt::format("PRM[{}]: {}", number, why));
}

} // namespace

} // namespace mbc::rt

using namespace mbc;
using namespace mbc::rt;

mbrt_status mbrt_read_parameter(mbrt_ctx* ctx, int form, double number,
                                double bit, double axis, double* out) {
  const double n = roundHalfAway(number);
  const ParameterSpec* spec =
      n >= 1.0 && n <= 99999.0 ? findParameter(static_cast<int>(n)) : nullptr;
  if (spec == nullptr) {
    return raise(*ctx, AlarmId::Unsupported,
                 fmt::format("PRM[{}]: parameter {} is not one mbc models "
                             "(docs/machine-profile.md lists them)",
                             number, n));
  }
  const int parameter = static_cast<int>(n);
  const bool perAxis = (form & MBRT_PARAMETER_AXIS) != 0;
  if (perAxis != spec->perAxis) {
    return outOfRange(*ctx, n,
                      spec->perAxis ? "a per-axis parameter needs /[axis]"
                                    : "the parameter is not per axis");
  }
  double value = ctx->profile.parameter(parameter);
  if (perAxis) {
    const double a = roundHalfAway(axis);
    if (a < 1.0 || a > ctx->axisCount()) {
      return outOfRange(*ctx, n,
                        fmt::format("axis {} (the machine has 1 to {})", axis,
                                    ctx->axisCount()));
    }
    value =
        axisParameterValue(ctx->profile, parameter, static_cast<int>(a) - 1);
  }
  if ((form & MBRT_PARAMETER_BIT) != 0) {
    const double b = roundHalfAway(bit);
    const bool bitParameter = spec->bits();
    if (!bitParameter || b < 0.0 || b > 7.0) {
      return outOfRange(*ctx, n,
                        bitParameter ? fmt::format("bit {} (0 to 7)", bit)
                                     : std::string("not a bit parameter"));
    }
    value = static_cast<double>(
        (static_cast<long>(value) >> static_cast<int>(b)) & 1);
  }
  *out = value;
  return 0;
}
