// The arithmetic, comparison and function semantics of Custom Macro B
// (spec §2.3, §3.2, §3.3): one implementation shared by the interpreter, the
// compiled code's runtime and the constant folder.
#include <mbc/arith.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

namespace mbc {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

/// Every result passes through here: overflow to infinity (or a NaN that
/// would be mistaken for vacant) is PS0111.
AlarmId finish(double result, Num* out) {
  if (!std::isfinite(result)) {
    return AlarmId::FloatOverflow;
  }
  *out = positiveZero(result);
  return AlarmId::None;
}

AlarmId evalMod(double a, double b, Num* out) {
  const double dividend = roundHalfAway(a);
  const double divisor = roundHalfAway(b);
  if (divisor == 0.0) {
    return AlarmId::ZeroDivide;
  }
  // fmod is exact and keeps the dividend's sign, as FANUC's MOD does; so
  // does the integer remainder, many times faster, where it is exact.
  if (std::fabs(dividend) < 0x1p53 && std::fabs(divisor) < 0x1p53) {
    return finish(static_cast<double>(static_cast<std::int64_t>(dividend) %
                                      static_cast<std::int64_t>(divisor)),
                  out);
  }
  return finish(std::fmod(dividend, divisor), out);
}

std::optional<std::int32_t> toInt32(double x) {
  const double rounded = roundHalfAway(x);
  if (rounded < std::numeric_limits<std::int32_t>::min() ||
      rounded > std::numeric_limits<std::int32_t>::max()) {
    return std::nullopt;
  }
  return static_cast<std::int32_t>(rounded);
}

AlarmId evalBitwise(BinOp op, double a, double b, Num* out) {
  const auto x = toInt32(a);
  const auto y = toInt32(b);
  if (!x || !y) {
    return AlarmId::IntegerOverflow;
  }
  std::int32_t result = 0;
  switch (op) {
    case BinOp::And:
      result = *x & *y;
      break;
    case BinOp::Or:
      result = *x | *y;
      break;
    default:
      result = *x ^ *y;
      break;
  }
  return finish(static_cast<double>(result), out);
}

/// sin (or cos, `cosine`) of 0 <= x <= 45 degrees; the values at 0, 30
/// and 45 are the exact ones rounded once (std::sin of 30 degrees in
/// radians is not quite 0.5).
double firstOctant(double x, bool cosine) {
  if (x == 0.0) {
    return cosine ? 1.0 : 0.0;
  }
  if (x == 30.0) {
    return cosine ? std::numbers::sqrt3 / 2.0 : 0.5;
  }
  if (x == 45.0) {
    return std::numbers::sqrt2 / 2.0;
  }
  const double radians = x / kDegPerRad;
  return cosine ? std::cos(radians) : std::sin(radians);
}

/// sin (or cos) of |degrees| by exact reduction to the first octant, so
/// that the usual identities hold bit for bit: SIN[-a] = -SIN[a],
/// COS[-a] = COS[a], SIN[a] = COS[90 - a], SIN[a + 360] = SIN[a], and the
/// multiples of 30 and 45 degrees give the exact values rounded once.
double trigOfMagnitude(double degrees, bool cosine) {
  const double a = std::fabs(degrees);
  // fmod is exact; an angle under one turn skips it (it is slow).
  const double turn = a < 360.0 ? a : std::fmod(a, 360.0);
  // Whole quarter turns: each subtraction is exact (Sterbenz).
  const int quarter = turn >= 270.0   ? 3
                      : turn >= 180.0 ? 2
                      : turn >= 90.0  ? 1
                                      : 0;
  const double x = turn - 90.0 * quarter;
  // sin(90q + x) is sin x, cos x, -sin x, -cos x for q = 0..3; cos(90q + x)
  // is cos x, -sin x, -cos x, sin x.
  const bool ofCosine = cosine != (quarter % 2 == 1);
  const bool negative = cosine ? quarter == 1 || quarter == 2 : quarter >= 2;
  const double v =
      x > 45.0 ? firstOctant(90.0 - x, !ofCosine) : firstOctant(x, ofCosine);
  return negative ? -v : v;
}

double sinDegrees(double degrees) {
  const double s = trigOfMagnitude(degrees, false);
  return positiveZero(degrees < 0.0 ? -s : s);
}

double cosDegrees(double degrees) {
  return positiveZero(trigOfMagnitude(degrees, true));
}

/// NAT = 0 reports angles as 0..360 instead of negative (parameter 6004#0).
double applyNat(double degrees, const MathParams& params) {
  if (params.nat || degrees >= 0.0) {
    return degrees;
  }
  const double wrapped = degrees + 360.0;
  return wrapped >= 360.0 ? 0.0 : wrapped;
}

AlarmId evalTan(double x, Num* out) {
  const double c = cosDegrees(x);
  if (c == 0.0) {
    return AlarmId::ZeroDivide;
  }
  return finish(sinDegrees(x) / c, out);
}

/// Inverse trig results that are a whole degree up to rounding noise are
/// made exact: ASIN[0.5] is 30, not 30.000000000000004, as SIN[30] is 0.5.
double snapDegrees(double degrees) {
  const double whole = std::round(degrees);
  return std::fabs(degrees - whole) < 1e-12 ? whole : degrees;
}

AlarmId evalAsin(double x, const MathParams& params, Num* out) {
  if (std::fabs(x) > 1.0) {
    return AlarmId::ArgumentOutOfRange;
  }
  return finish(
      applyNat(positiveZero(snapDegrees(std::asin(x) * kDegPerRad)), params),
      out);
}

AlarmId evalAcos(double x, Num* out) {
  if (std::fabs(x) > 1.0) {
    return AlarmId::ArgumentOutOfRange;
  }
  return finish(snapDegrees(std::acos(x) * kDegPerRad), out);
}

AlarmId evalAtan2(double y, double x, const MathParams& params, Num* out) {
  // +0.0 keeps atan2 from answering -180 for a zero Y side.
  const double degrees =
      snapDegrees(std::atan2(positiveZero(y), positiveZero(x)) * kDegPerRad);
  return finish(applyNat(positiveZero(degrees), params), out);
}

AlarmId evalSqrt(double x, Num* out) {
  if (x < 0.0) {
    return AlarmId::ArgumentOutOfRange;
  }
  return finish(std::sqrt(x), out);
}

AlarmId evalLn(double x, Num* out) {
  if (x <= 0.0) {
    return AlarmId::ArgumentOutOfRange;
  }
  return finish(std::log(x), out);
}

AlarmId evalPow(double base, double exponent, Num* out) {
  if (base < 0.0 && std::trunc(exponent) != exponent) {
    return AlarmId::ArgumentOutOfRange;
  }
  if (base == 0.0 && exponent < 0.0) {
    return AlarmId::ZeroDivide;
  }
  return finish(std::pow(base, exponent), out);
}

double awayFromZero(double x) {
  return x < 0.0 ? std::floor(x) : std::ceil(x);
}

/// The largest BCD word: eight decimal digits, one PMC double word.
constexpr std::uint64_t kMaxBcd = 0x9999'9999;
constexpr std::uint64_t kMaxBcdDecimal = 99'999'999;

/// BIN/BCD work on non-negative whole numbers (spec §3.3).
std::optional<std::uint64_t> toCount(double x, std::uint64_t limit) {
  const double rounded = roundHalfAway(x);
  if (rounded < 0.0 || rounded > static_cast<double>(limit)) {
    return std::nullopt;
  }
  return static_cast<std::uint64_t>(rounded);
}

AlarmId evalBin(double x, Num* out) {
  auto bcd = toCount(x, kMaxBcd);
  if (!bcd) {
    return AlarmId::ArgumentOutOfRange;
  }
  std::uint64_t result = 0;
  std::uint64_t scale = 1;
  for (std::uint64_t rest = *bcd; rest != 0; rest >>= 4, scale *= 10) {
    const std::uint64_t nibble = rest & 0xF;
    if (nibble > 9) {
      return AlarmId::ArgumentOutOfRange;
    }
    result += nibble * scale;
  }
  return finish(static_cast<double>(result), out);
}

AlarmId evalBcd(double x, Num* out) {
  auto value = toCount(x, kMaxBcdDecimal);
  if (!value) {
    return AlarmId::ArgumentOutOfRange;
  }
  std::uint64_t result = 0;
  int shift = 0;
  for (std::uint64_t rest = *value; rest != 0; rest /= 10, shift += 4) {
    result |= (rest % 10) << shift;
  }
  return finish(static_cast<double>(result), out);
}

AlarmId evalTrig(Builtin f, double x, const MathParams& params, Num* out) {
  switch (f) {
    case Builtin::Sin:
      return finish(sinDegrees(x), out);
    case Builtin::Cos:
      return finish(cosDegrees(x), out);
    case Builtin::Tan:
      return evalTan(x, out);
    case Builtin::Asin:
      return evalAsin(x, params, out);
    case Builtin::Acos:
      return evalAcos(x, out);
    default:
      return finish(
          applyNat(positiveZero(snapDegrees(std::atan(x) * kDegPerRad)),
                   params),
          out);
  }
}

AlarmId evalRounding(Builtin f, double x, Num* out) {
  switch (f) {
    case Builtin::Abs:
      return finish(std::fabs(x), out);
    case Builtin::Round:
      return finish(roundHalfAway(x), out);
    case Builtin::Fix:
      return finish(std::trunc(x), out);
    default:
      return finish(awayFromZero(x), out);
  }
}

} // namespace

AlarmId evalBinary(BinOp op, Num a, Num b, Num* out) {
  const double x = numeric(a);
  const double y = numeric(b);
  switch (op) {
    case BinOp::Add:
      return finish(x + y, out);
    case BinOp::Sub:
      return finish(x - y, out);
    case BinOp::Mul:
      return finish(x * y, out);
    case BinOp::Div:
      return y == 0.0 ? AlarmId::ZeroDivide : finish(x / y, out);
    case BinOp::Mod:
      return evalMod(x, y, out);
    case BinOp::And:
    case BinOp::Or:
    case BinOp::Xor:
      return evalBitwise(op, x, y, out);
  }
  return AlarmId::IllegalExpressionFormat;
}

Num negate(Num a) {
  return positiveZero(-numeric(a));
}

bool evalCompare(RelOp op, Num a, Num b) {
  const bool vacantA = isVacant(a);
  const bool vacantB = isVacant(b);
  const bool equal = vacantA || vacantB ? vacantA && vacantB : a == b;
  const double x = numeric(a);
  const double y = numeric(b);
  switch (op) {
    case RelOp::Eq:
      return equal;
    case RelOp::Ne:
      return !equal;
    case RelOp::Gt:
      return x > y;
    case RelOp::Ge:
      return x >= y;
    case RelOp::Lt:
      return x < y;
    case RelOp::Le:
      return x <= y;
  }
  return false;
}

AlarmId evalBuiltin(Builtin f, const Num* args, const MathParams& params,
                    Num* out) {
  const double x = numeric(args[0]);
  switch (f) {
    case Builtin::Sin:
    case Builtin::Cos:
    case Builtin::Tan:
    case Builtin::Asin:
    case Builtin::Acos:
    case Builtin::Atan:
      return evalTrig(f, x, params, out);
    case Builtin::Atan2:
      return evalAtan2(x, numeric(args[1]), params, out);
    case Builtin::Sqrt:
      return evalSqrt(x, out);
    case Builtin::Abs:
    case Builtin::Round:
    case Builtin::Fix:
    case Builtin::Fup:
      return evalRounding(f, x, out);
    case Builtin::Ln:
      return evalLn(x, out);
    case Builtin::Exp:
      return finish(std::exp(x), out);
    case Builtin::Pow:
      return evalPow(x, numeric(args[1]), out);
    case Builtin::Adp:
      return finish(x, out);
    case Builtin::Bin:
      return evalBin(x, out);
    case Builtin::Bcd:
      return evalBcd(x, out);
  }
  return AlarmId::ImproperCommand;
}

namespace {

struct BuiltinRow {
  const char* name;
  int arity;
};

constexpr std::array kBuiltinTable = {
#define BUILTIN(Id, Name, Arity) BuiltinRow{Name, Arity},
#include <mbc/builtins.def>
};

const BuiltinRow* builtinRow(Builtin f) {
  const auto index = static_cast<std::size_t>(f);
  return index < kBuiltinTable.size() ? &kBuiltinTable[index] : nullptr;
}

} // namespace

const char* builtinName(Builtin f) {
  const BuiltinRow* row = builtinRow(f);
  return row ? row->name : "";
}

int builtinArity(Builtin f) {
  const BuiltinRow* row = builtinRow(f);
  return row ? row->arity : 0;
}

} // namespace mbc
