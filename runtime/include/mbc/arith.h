// The arithmetic, comparison and function semantics of Custom Macro B, shared
// by every engine and by constant folding so that they cannot disagree.
// Each operation that can fail returns the alarm it raises (AlarmId::None on
// success) and writes its result through `out`.
#pragma once

#include <mbc/alarm.h>
#include <mbc/value.h>

#include <cmath>
#include <cstdint>

namespace mbc {

enum class BinOp : std::uint8_t { Add, Sub, Mul, Div, Mod, And, Or, Xor };

enum class RelOp : std::uint8_t { Eq, Ne, Gt, Ge, Lt, Le };

enum class Builtin : std::uint8_t {
#define BUILTIN(Id, Name, Arity) Id,
#include <mbc/builtins.def>
};

/// Parameters of the machine profile that change function results.
struct MathParams {
  /// 6004#0 NAT: 0 gives ASIN 270..90 and ATAN 0..360; 1 gives -90..90 and
  /// -180..180 (spec §3.3).
  bool nat = false;
};

/// a op b with vacant read as 0. Division by zero is PS0112, a result
/// outside the double range PS0111, AND/OR/XOR operands outside 32 bits
/// PS0110.
AlarmId evalBinary(BinOp op, Num a, Num b, Num* out);

/// Unary minus (vacant reads as 0).
Num negate(Num a);

/// EQ and NE tell vacant from 0; the others read vacant as 0 (spec §2.3c).
bool evalCompare(RelOp op, Num a, Num b);

/// f(args) with vacant arguments read as 0. `args` has the builtin's arity.
/// ADP is handled by the caller (it needs to know how a local was set); here
/// it returns its argument.
AlarmId evalBuiltin(Builtin f, const Num* args, const MathParams& params,
                    Num* out);

/// -0.0 prints as "-0" in some tools and makes ATAN2 pick the wrong branch;
/// no macro value is ever -0.0, so compiled code adds and subtracts without
/// checking.
inline double positiveZero(double x) {
  return x == 0.0 ? 0.0 : x;
}

/// Rounds half away from zero to an integer: variable numbers, AND/OR/XOR
/// operands, integer addresses and ROUND in macro statements (spec §2.2).
/// The same result as std::round, inline: that is a libm call, and NC
/// blocks round every address. Every double from 2^52 up is whole; below,
/// adding the largest double under 0.5 and truncating through int64 is exact.
inline double roundHalfAway(double x) {
  if (!(std::fabs(x) < 0x1p52)) {
    return x; // also infinity and NaN
  }
  const double biased = x + std::copysign(0.49999999999999994, x);
  return std::copysign(static_cast<double>(static_cast<std::int64_t>(biased)),
                       x);
}

/// Name and arity of a builtin, from builtins.def.
const char* builtinName(Builtin f);
int builtinArity(Builtin f);

} // namespace mbc
