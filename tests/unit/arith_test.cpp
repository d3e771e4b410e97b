// Unit tests of the shared Macro B arithmetic (arith.h) and the alarm table
// (alarm.h): operators, comparisons with vacant, every builtin and its alarms.
#include <mbc/alarm.h>
#include <mbc/arith.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace mbc {
namespace {

constexpr double kHuge = std::numeric_limits<double>::max();

/// Result of a binary operation that must succeed.
double binary(BinOp op, Num a, Num b) {
  Num out = -12345.0;
  EXPECT_EQ(evalBinary(op, a, b, &out), AlarmId::None);
  return out;
}

AlarmId binaryAlarm(BinOp op, Num a, Num b) {
  Num out = 0.0;
  return evalBinary(op, a, b, &out);
}

/// Result of a builtin that must succeed.
double call(Builtin f, std::vector<Num> args, bool nat = false) {
  EXPECT_EQ(static_cast<int>(args.size()), builtinArity(f));
  Num out = -12345.0;
  EXPECT_EQ(evalBuiltin(f, args.data(), MathParams{nat}, &out), AlarmId::None)
      << builtinName(f);
  return out;
}

AlarmId callAlarm(Builtin f, std::vector<Num> args, bool nat = false) {
  Num out = 0.0;
  return evalBuiltin(f, args.data(), MathParams{nat}, &out);
}

bool isNegativeZero(double x) {
  return x == 0.0 && std::signbit(x);
}

TEST(ArithBinary, AddSubMulDiv) {
  EXPECT_EQ(binary(BinOp::Add, 1.5, 2.25), 3.75);
  EXPECT_EQ(binary(BinOp::Sub, 1.5, 2.25), -0.75);
  EXPECT_EQ(binary(BinOp::Mul, -1.5, 4.0), -6.0);
  EXPECT_EQ(binary(BinOp::Div, 7.0, 2.0), 3.5);
  EXPECT_EQ(binary(BinOp::Div, -9.0, 3.0), -3.0);
}

TEST(ArithBinary, VacantReadsAsZero) {
  EXPECT_EQ(binary(BinOp::Add, vacant(), vacant()), 0.0);
  EXPECT_FALSE(isVacant(binary(BinOp::Add, vacant(), vacant())));
  EXPECT_EQ(binary(BinOp::Mul, vacant(), 5.0), 0.0);
  EXPECT_EQ(binary(BinOp::Sub, 157.0, vacant()), 157.0);
  EXPECT_EQ(binary(BinOp::Sub, vacant(), 2.0), -2.0);
  EXPECT_EQ(binary(BinOp::Div, vacant(), 4.0), 0.0);
  EXPECT_EQ(binary(BinOp::Mod, vacant(), 4.0), 0.0);
  EXPECT_EQ(binary(BinOp::Or, vacant(), 6.0), 6.0);
}

TEST(ArithBinary, DivisionByZeroAlarms) {
  EXPECT_EQ(binaryAlarm(BinOp::Div, 1.0, 0.0), AlarmId::ZeroDivide);
  EXPECT_EQ(binaryAlarm(BinOp::Div, 0.0, 0.0), AlarmId::ZeroDivide);
  EXPECT_EQ(binaryAlarm(BinOp::Div, 1.0, vacant()), AlarmId::ZeroDivide);
}

TEST(ArithBinary, OverflowAlarms) {
  EXPECT_EQ(binaryAlarm(BinOp::Add, kHuge, kHuge), AlarmId::FloatOverflow);
  EXPECT_EQ(binaryAlarm(BinOp::Sub, -kHuge, kHuge), AlarmId::FloatOverflow);
  EXPECT_EQ(binaryAlarm(BinOp::Mul, kHuge, 2.0), AlarmId::FloatOverflow);
  EXPECT_EQ(binaryAlarm(BinOp::Div, kHuge, 0.5), AlarmId::FloatOverflow);
}

TEST(ArithBinary, AlarmLeavesNoResult) {
  Num out = 42.0;
  EXPECT_EQ(evalBinary(BinOp::Div, 1.0, 0.0, &out), AlarmId::ZeroDivide);
  EXPECT_EQ(out, 42.0);
}

TEST(ArithBinary, NoNegativeZero) {
  EXPECT_FALSE(isNegativeZero(binary(BinOp::Mul, -1.0, 0.0)));
  EXPECT_FALSE(isNegativeZero(binary(BinOp::Div, 0.0, -5.0)));
  EXPECT_FALSE(isNegativeZero(binary(BinOp::Mod, -6.0, 3.0)));
}

TEST(ArithBinary, ModTakesSignOfDividend) {
  EXPECT_EQ(binary(BinOp::Mod, 7.0, 3.0), 1.0);
  EXPECT_EQ(binary(BinOp::Mod, -7.0, 3.0), -1.0);
  EXPECT_EQ(binary(BinOp::Mod, 7.0, -3.0), 1.0);
  EXPECT_EQ(binary(BinOp::Mod, -7.0, -3.0), -1.0);
  EXPECT_EQ(binary(BinOp::Mod, 6.0, 3.0), 0.0);
}

TEST(ArithBinary, ModRoundsOperandsFirst) {
  EXPECT_EQ(binary(BinOp::Mod, 7.5, 3.0), 2.0);   // 8 MOD 3
  EXPECT_EQ(binary(BinOp::Mod, 7.4, 2.6), 1.0);   // 7 MOD 3
  EXPECT_EQ(binary(BinOp::Mod, -7.5, 3.0), -2.0); // -8 MOD 3
  EXPECT_EQ(binaryAlarm(BinOp::Mod, 5.0, 0.0), AlarmId::ZeroDivide);
  EXPECT_EQ(binaryAlarm(BinOp::Mod, 5.0, 0.4), AlarmId::ZeroDivide);
  EXPECT_EQ(binaryAlarm(BinOp::Mod, 5.0, vacant()), AlarmId::ZeroDivide);
}

// Below 2^53 MOD divides as integers; beyond, fmod: both give its bits.
TEST(ArithBinary, ModOfLargeNumbersIsExact) {
  const double big = 0x1p53 - 1.0;
  EXPECT_EQ(binary(BinOp::Mod, big, 10.0), std::fmod(big, 10.0));
  EXPECT_EQ(binary(BinOp::Mod, -big, 7.0), std::fmod(-big, 7.0));
  EXPECT_EQ(binary(BinOp::Mod, 1e300, 7.0), std::fmod(1e300, 7.0));
  EXPECT_EQ(binary(BinOp::Mod, 12.0, 1e20), 12.0);
  EXPECT_EQ(binary(BinOp::Mod, 0x1p60, 0x1p53 - 1.0),
            std::fmod(0x1p60, 0x1p53 - 1.0));
  EXPECT_FALSE(isNegativeZero(binary(BinOp::Mod, -0x1p60, 2.0)));
}

TEST(ArithBinary, Bitwise) {
  EXPECT_EQ(binary(BinOp::And, 12.0, 10.0), 8.0);
  EXPECT_EQ(binary(BinOp::Or, 12.0, 3.0), 15.0);
  EXPECT_EQ(binary(BinOp::Xor, 5.0, 1.0), 4.0);
  EXPECT_EQ(binary(BinOp::And, 2.6, 3.0), 3.0);
  EXPECT_EQ(binary(BinOp::Or, 2.4, 0.5), 3.0); // 2 OR 1
  EXPECT_EQ(binary(BinOp::And, vacant(), 7.0), 0.0);
}

TEST(ArithBinary, BitwiseTwosComplement) {
  EXPECT_EQ(binary(BinOp::And, -1.0, 255.0), 255.0);
  EXPECT_EQ(binary(BinOp::Or, -8.0, 3.0), -5.0);
  EXPECT_EQ(binary(BinOp::Xor, -1.0, 0.0), -1.0);
  EXPECT_EQ(binary(BinOp::Xor, 2147483647.0, -2147483648.0), -1.0);
}

TEST(ArithBinary, BitwiseRangeAlarms) {
  EXPECT_EQ(binaryAlarm(BinOp::And, 2147483648.0, 1.0),
            AlarmId::IntegerOverflow);
  EXPECT_EQ(binaryAlarm(BinOp::Or, 1.0, -2147483649.0),
            AlarmId::IntegerOverflow);
  EXPECT_EQ(binaryAlarm(BinOp::Xor, 1e20, 1.0), AlarmId::IntegerOverflow);
  // 2147483646.5 rounds away from zero to 2^31 - 1, still in range.
  EXPECT_EQ(binary(BinOp::And, 2147483646.5, 1.0), 1.0);
  EXPECT_EQ(binaryAlarm(BinOp::And, 2147483647.5, 1.0),
            AlarmId::IntegerOverflow);
}

TEST(ArithNegate, Values) {
  EXPECT_EQ(negate(2.5), -2.5);
  EXPECT_EQ(negate(-3.0), 3.0);
  EXPECT_EQ(negate(vacant()), 0.0);
  EXPECT_FALSE(isVacant(negate(vacant())));
  EXPECT_FALSE(isNegativeZero(negate(0.0)));
  EXPECT_FALSE(isNegativeZero(negate(vacant())));
}

// Spec §2.3c, #1 vacant and #1 = 0 columns.
TEST(ArithCompare, VacantTable) {
  const Num v = vacant();
  EXPECT_TRUE(evalCompare(RelOp::Eq, v, vacant()));
  EXPECT_FALSE(evalCompare(RelOp::Eq, 0.0, vacant()));
  EXPECT_TRUE(evalCompare(RelOp::Ne, v, 0.0));
  EXPECT_FALSE(evalCompare(RelOp::Ne, 0.0, 0.0));
  EXPECT_TRUE(evalCompare(RelOp::Ge, v, vacant()));
  EXPECT_TRUE(evalCompare(RelOp::Ge, 0.0, vacant()));
  EXPECT_FALSE(evalCompare(RelOp::Gt, v, 0.0));
  EXPECT_FALSE(evalCompare(RelOp::Gt, 0.0, 0.0));
  EXPECT_TRUE(evalCompare(RelOp::Le, v, vacant()));
  EXPECT_TRUE(evalCompare(RelOp::Le, 0.0, vacant()));
  EXPECT_FALSE(evalCompare(RelOp::Lt, v, 0.0));
  EXPECT_FALSE(evalCompare(RelOp::Lt, 0.0, 0.0));
}

TEST(ArithCompare, VacantNeverEqualsANumber) {
  EXPECT_FALSE(evalCompare(RelOp::Eq, vacant(), 0.0));
  EXPECT_FALSE(evalCompare(RelOp::Eq, 0.0, vacant()));
  EXPECT_FALSE(evalCompare(RelOp::Eq, vacant(), 5.0));
  EXPECT_TRUE(evalCompare(RelOp::Ne, 5.0, vacant()));
  EXPECT_FALSE(evalCompare(RelOp::Ne, vacant(), vacant()));
}

TEST(ArithCompare, Numbers) {
  EXPECT_TRUE(evalCompare(RelOp::Eq, 1.5, 1.5));
  EXPECT_FALSE(evalCompare(RelOp::Eq, 0.1 + 0.2, 0.3)); // no tolerance
  EXPECT_TRUE(evalCompare(RelOp::Ne, 1.0, 2.0));
  EXPECT_TRUE(evalCompare(RelOp::Gt, 2.0, 1.0));
  EXPECT_FALSE(evalCompare(RelOp::Gt, 1.0, 1.0));
  EXPECT_TRUE(evalCompare(RelOp::Ge, 1.0, 1.0));
  EXPECT_TRUE(evalCompare(RelOp::Lt, -1.0, 0.0));
  EXPECT_FALSE(evalCompare(RelOp::Lt, 1.0, 1.0));
  EXPECT_TRUE(evalCompare(RelOp::Le, 1.0, 1.0));
  EXPECT_FALSE(evalCompare(RelOp::Le, 2.0, 1.0));
  EXPECT_TRUE(evalCompare(RelOp::Gt, 1.0, vacant()));
  EXPECT_TRUE(evalCompare(RelOp::Lt, vacant(), 1.0));
}

TEST(ArithSinCos, ExactAtMultiplesOfThirty) {
  EXPECT_EQ(call(Builtin::Sin, {30.0}), 0.5);
  EXPECT_EQ(call(Builtin::Sin, {90.0}), 1.0);
  EXPECT_EQ(call(Builtin::Sin, {150.0}), 0.5);
  EXPECT_EQ(call(Builtin::Sin, {180.0}), 0.0);
  EXPECT_EQ(call(Builtin::Sin, {210.0}), -0.5);
  EXPECT_EQ(call(Builtin::Sin, {270.0}), -1.0);
  EXPECT_EQ(call(Builtin::Sin, {330.0}), -0.5);
  EXPECT_EQ(call(Builtin::Sin, {360.0}), 0.0);
  EXPECT_EQ(call(Builtin::Cos, {0.0}), 1.0);
  EXPECT_EQ(call(Builtin::Cos, {60.0}), 0.5);
  EXPECT_EQ(call(Builtin::Cos, {90.0}), 0.0);
  EXPECT_EQ(call(Builtin::Cos, {120.0}), -0.5);
  EXPECT_EQ(call(Builtin::Cos, {180.0}), -1.0);
  EXPECT_EQ(call(Builtin::Cos, {270.0}), 0.0);
  EXPECT_EQ(call(Builtin::Cos, {300.0}), 0.5);
}

TEST(ArithSinCos, ReducesAnyNumberOfTurns) {
  EXPECT_EQ(call(Builtin::Sin, {-30.0}), -0.5);
  EXPECT_EQ(call(Builtin::Sin, {-90.0}), -1.0);
  EXPECT_EQ(call(Builtin::Sin, {390.0}), 0.5);
  EXPECT_EQ(call(Builtin::Sin, {3600.0 + 90.0}), 1.0);
  EXPECT_EQ(call(Builtin::Cos, {-60.0}), 0.5);
  EXPECT_EQ(call(Builtin::Cos, {720.0 + 180.0}), -1.0);
  EXPECT_FALSE(isNegativeZero(call(Builtin::Sin, {-180.0})));
  EXPECT_FALSE(isNegativeZero(call(Builtin::Sin, {-360.0})));
  EXPECT_FALSE(isNegativeZero(call(Builtin::Cos, {-90.0})));
}

// An angle one ulp off a multiple of 30 is not exact, though its quotient
// by 30 rounds to a whole number.
TEST(ArithSinCos, OnlyExactMultiplesAreExact) {
  const double off150 = std::nextafter(150.0, 151.0);
  EXPECT_EQ(call(Builtin::Sin, {off150}),
            std::sin(off150 / (180.0 / std::numbers::pi)));
  EXPECT_NE(call(Builtin::Sin, {off150}), 0.5);
  EXPECT_NE(call(Builtin::Cos, {std::nextafter(60.0, 61.0)}), 0.5);
  EXPECT_EQ(call(Builtin::Sin, {-359.0}), call(Builtin::Sin, {1.0}));
  EXPECT_EQ(call(Builtin::Cos, {1e6 * 360.0 + 60.0}), 0.5);
}

TEST(ArithSinCos, OtherAngles) {
  EXPECT_NEAR(call(Builtin::Sin, {60.0}), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(call(Builtin::Sin, {45.0}), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(call(Builtin::Sin, {-45.0}), -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(call(Builtin::Sin, {1.0}), 0.01745240643728351, 1e-15);
  EXPECT_NEAR(call(Builtin::Cos, {30.0}), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(call(Builtin::Cos, {135.0}), -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(call(Builtin::Cos, {-1.0}), 0.9998476951563913, 1e-15);
}

// sqrt(3)/2 and sqrt(2)/2 rounded once, wherever the angle lies: SIN[60]
// EQ COS[30] holds, and TAN[45] is 1.
TEST(ArithSinCos, ExactAtMultiplesOfFortyFiveAndThirty) {
  const double halfSqrt3 = std::numbers::sqrt3 / 2.0;
  const double halfSqrt2 = std::numbers::sqrt2 / 2.0;
  for (double a : {60.0, 120.0, -240.0, -300.0, 420.0}) {
    EXPECT_EQ(call(Builtin::Sin, {a}), halfSqrt3) << a;
  }
  for (double a : {30.0, -30.0, 330.0, 390.0}) {
    EXPECT_EQ(call(Builtin::Cos, {a}), halfSqrt3) << a;
  }
  EXPECT_EQ(call(Builtin::Sin, {240.0}), -halfSqrt3);
  EXPECT_EQ(call(Builtin::Cos, {150.0}), -halfSqrt3);
  for (double a : {45.0, 135.0, -225.0, -315.0}) {
    EXPECT_EQ(call(Builtin::Sin, {a}), halfSqrt2) << a;
  }
  EXPECT_EQ(call(Builtin::Cos, {-45.0}), halfSqrt2);
  EXPECT_EQ(call(Builtin::Cos, {225.0}), -halfSqrt2);
  EXPECT_EQ(call(Builtin::Tan, {45.0}), 1.0);
  EXPECT_EQ(call(Builtin::Tan, {-45.0}), -1.0);
  EXPECT_EQ(call(Builtin::Tan, {135.0}), -1.0);
}

TEST(ArithSinCos, IdentitiesHoldBitForBit) {
  for (double a = 0.25; a < 400.0; a += 0.25) {
    EXPECT_EQ(call(Builtin::Sin, {-a}), -call(Builtin::Sin, {a})) << a;
    EXPECT_EQ(call(Builtin::Cos, {-a}), call(Builtin::Cos, {a})) << a;
    EXPECT_EQ(call(Builtin::Sin, {a}), call(Builtin::Cos, {90.0 - a})) << a;
    EXPECT_EQ(call(Builtin::Sin, {a + 360.0}), call(Builtin::Sin, {a})) << a;
  }
}

TEST(ArithSinCos, VacantIsZeroDegrees) {
  EXPECT_EQ(call(Builtin::Sin, {vacant()}), 0.0);
  EXPECT_EQ(call(Builtin::Cos, {vacant()}), 1.0);
  EXPECT_EQ(call(Builtin::Tan, {vacant()}), 0.0);
}

TEST(ArithTan, Values) {
  EXPECT_EQ(call(Builtin::Tan, {0.0}), 0.0);
  EXPECT_EQ(call(Builtin::Tan, {180.0}), 0.0);
  EXPECT_NEAR(call(Builtin::Tan, {45.0}), 1.0, 1e-15);
  EXPECT_NEAR(call(Builtin::Tan, {-45.0}), -1.0, 1e-15);
  EXPECT_NEAR(call(Builtin::Tan, {60.0}), std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(call(Builtin::Tan, {30.0}), 1.0 / std::sqrt(3.0), 1e-15);
}

TEST(ArithTan, ZeroCosineAlarms) {
  EXPECT_EQ(callAlarm(Builtin::Tan, {90.0}), AlarmId::ZeroDivide);
  EXPECT_EQ(callAlarm(Builtin::Tan, {270.0}), AlarmId::ZeroDivide);
  EXPECT_EQ(callAlarm(Builtin::Tan, {-90.0}), AlarmId::ZeroDivide);
  EXPECT_EQ(callAlarm(Builtin::Tan, {450.0}), AlarmId::ZeroDivide);
}

TEST(ArithAsin, NatZeroRange) {
  EXPECT_EQ(call(Builtin::Asin, {1.0}), 90.0);
  EXPECT_EQ(call(Builtin::Asin, {0.0}), 0.0);
  EXPECT_EQ(call(Builtin::Asin, {-1.0}), 270.0);
  EXPECT_NEAR(call(Builtin::Asin, {0.5}), 30.0, 1e-12);
  EXPECT_NEAR(call(Builtin::Asin, {-0.5}), 330.0, 1e-12);
  EXPECT_EQ(call(Builtin::Asin, {vacant()}), 0.0);
  EXPECT_FALSE(isNegativeZero(call(Builtin::Asin, {-0.0})));
}

TEST(ArithAsin, NatOneRange) {
  EXPECT_EQ(call(Builtin::Asin, {1.0}, true), 90.0);
  EXPECT_EQ(call(Builtin::Asin, {-1.0}, true), -90.0);
  EXPECT_NEAR(call(Builtin::Asin, {-0.5}, true), -30.0, 1e-12);
}

TEST(ArithAsinAcos, DomainAlarms) {
  EXPECT_EQ(callAlarm(Builtin::Asin, {1.0000001}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Asin, {-2.0}, true),
            AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Acos, {1.5}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Acos, {-1.0000001}),
            AlarmId::ArgumentOutOfRange);
}

TEST(ArithAcos, Values) {
  EXPECT_EQ(call(Builtin::Acos, {1.0}), 0.0);
  EXPECT_EQ(call(Builtin::Acos, {0.0}), 90.0);
  EXPECT_EQ(call(Builtin::Acos, {-1.0}), 180.0);
  EXPECT_NEAR(call(Builtin::Acos, {0.5}), 60.0, 1e-12);
  EXPECT_NEAR(call(Builtin::Acos, {-0.5}), 120.0, 1e-12);
  EXPECT_NEAR(call(Builtin::Acos, {-0.5}, true), 120.0, 1e-12);
  EXPECT_EQ(call(Builtin::Acos, {vacant()}), 90.0);
}

TEST(ArithAtan, OneArgument) {
  EXPECT_EQ(call(Builtin::Atan, {1.0}), 45.0);
  EXPECT_EQ(call(Builtin::Atan, {0.0}), 0.0);
  EXPECT_EQ(call(Builtin::Atan, {-1.0}), 315.0);
  EXPECT_EQ(call(Builtin::Atan, {-1.0}, true), -45.0);
  EXPECT_NEAR(call(Builtin::Atan, {1e300}), 90.0, 1e-12);
  EXPECT_NEAR(call(Builtin::Atan, {-1e300}, true), -90.0, 1e-12);
  EXPECT_EQ(call(Builtin::Atan, {vacant()}), 0.0);
}

TEST(ArithAtan2, NatZeroRange) {
  EXPECT_EQ(call(Builtin::Atan2, {-1.0, -1.0}), 225.0);
  EXPECT_EQ(call(Builtin::Atan2, {0.0, -1.0}), 180.0);
  EXPECT_EQ(call(Builtin::Atan2, {1.0, 0.0}), 90.0);
  EXPECT_EQ(call(Builtin::Atan2, {-1.0, 0.0}), 270.0);
  EXPECT_EQ(call(Builtin::Atan2, {1.0, 1.0}), 45.0);
  EXPECT_EQ(call(Builtin::Atan2, {0.0, 1.0}), 0.0);
  EXPECT_EQ(call(Builtin::Atan2, {-0.0, -1.0}), 180.0);
}

TEST(ArithAtan2, NatOneRange) {
  EXPECT_EQ(call(Builtin::Atan2, {-1.0, -1.0}, true), -135.0);
  EXPECT_EQ(call(Builtin::Atan2, {0.0, -1.0}, true), 180.0);
  EXPECT_EQ(call(Builtin::Atan2, {-0.0, -1.0}, true), 180.0);
  EXPECT_EQ(call(Builtin::Atan2, {-1.0, 0.0}, true), -90.0);
  EXPECT_EQ(call(Builtin::Atan2, {1.0, -1.0}, true), 135.0);
}

TEST(ArithAtan2, ZeroOverZeroAndVacant) {
  EXPECT_EQ(call(Builtin::Atan2, {0.0, 0.0}), 0.0);
  EXPECT_EQ(call(Builtin::Atan2, {0.0, 0.0}, true), 0.0);
  EXPECT_EQ(call(Builtin::Atan2, {vacant(), vacant()}), 0.0);
  EXPECT_EQ(call(Builtin::Atan2, {vacant(), -2.0}), 180.0);
  EXPECT_EQ(call(Builtin::Atan2, {3.0, vacant()}), 90.0);
}

TEST(ArithSqrt, ValuesAndAlarm) {
  EXPECT_EQ(call(Builtin::Sqrt, {16.0}), 4.0);
  EXPECT_EQ(call(Builtin::Sqrt, {0.0}), 0.0);
  EXPECT_EQ(call(Builtin::Sqrt, {vacant()}), 0.0);
  EXPECT_NEAR(call(Builtin::Sqrt, {2.0}), 1.4142135623730951, 1e-15);
  EXPECT_EQ(callAlarm(Builtin::Sqrt, {-1e-9}), AlarmId::ArgumentOutOfRange);
}

TEST(ArithAbs, Values) {
  EXPECT_EQ(call(Builtin::Abs, {-2.5}), 2.5);
  EXPECT_EQ(call(Builtin::Abs, {2.5}), 2.5);
  EXPECT_EQ(call(Builtin::Abs, {vacant()}), 0.0);
}

TEST(ArithRound, HalfAwayFromZero) {
  EXPECT_EQ(call(Builtin::Round, {1.5}), 2.0);
  EXPECT_EQ(call(Builtin::Round, {2.5}), 3.0);
  EXPECT_EQ(call(Builtin::Round, {-1.5}), -2.0);
  EXPECT_EQ(call(Builtin::Round, {1.4999999}), 1.0);
  EXPECT_EQ(call(Builtin::Round, {-1.4}), -1.0);
  EXPECT_EQ(call(Builtin::Round, {vacant()}), 0.0);
  EXPECT_FALSE(isNegativeZero(call(Builtin::Round, {-0.4})));
  EXPECT_EQ(roundHalfAway(0.5), 1.0);
  EXPECT_EQ(roundHalfAway(-0.5), -1.0);
  EXPECT_EQ(roundHalfAway(-2.5), -3.0);
  EXPECT_EQ(roundHalfAway(3.49), 3.0);
}

// The inline rounding must give std::round's bits for every double: next to
// the halves, at the limits of exact int64 conversion, for the specials and
// signed zeros, and for random numbers of every magnitude.
TEST(ArithRound, SameBitsAsStdRound) {
  std::vector<double> samples = {0.0,
                                 -0.0,
                                 0.49999999999999994,
                                 0.5,
                                 -0.5,
                                 1e-300,
                                 -1e-300,
                                 0x1p52,
                                 -0x1p52,
                                 0x1p53,
                                 0x1p63,
                                 -0x1p63,
                                 1e300,
                                 std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity()};
  for (double whole = -4.0; whole <= 4.0; whole += 1.0) {
    for (double base : {whole + 0.5, 0x1p52 - whole, 0x1p51 + whole + 0.5}) {
      samples.push_back(base);
      samples.push_back(std::nextafter(base, 0.0));
      samples.push_back(std::nextafter(base, 1e308));
    }
  }
  std::uint64_t state = 88172645463325252ULL; // xorshift: reproducible
  for (int i = 0; i < 200000; ++i) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    const double unit = static_cast<double>(state >> 11) * 0x1p-53;
    samples.push_back((unit - 0.5) * std::ldexp(1.0, i % 70));
  }
  for (double x : samples) {
    const double expected = std::round(x);
    const double got = roundHalfAway(x);
    EXPECT_EQ(std::signbit(got), std::signbit(expected)) << x;
    EXPECT_EQ(got, expected) << std::hexfloat << x;
  }
  EXPECT_TRUE(std::isnan(roundHalfAway(std::nan(""))));
}

TEST(ArithFixFup, Positive) {
  EXPECT_EQ(call(Builtin::Fix, {1.2}), 1.0);
  EXPECT_EQ(call(Builtin::Fix, {1.9}), 1.0);
  EXPECT_EQ(call(Builtin::Fup, {1.2}), 2.0);
  EXPECT_EQ(call(Builtin::Fup, {2.0}), 2.0);
}

TEST(ArithFixFup, NegativeGoTowardAndAwayFromZero) {
  EXPECT_EQ(call(Builtin::Fix, {-1.2}), -1.0);
  EXPECT_EQ(call(Builtin::Fix, {-1.9}), -1.0);
  EXPECT_EQ(call(Builtin::Fup, {-1.2}), -2.0);
  EXPECT_EQ(call(Builtin::Fup, {-2.0}), -2.0);
  EXPECT_FALSE(isNegativeZero(call(Builtin::Fix, {-0.5})));
}

TEST(ArithFixFup, Vacant) {
  EXPECT_EQ(call(Builtin::Fix, {vacant()}), 0.0);
  EXPECT_EQ(call(Builtin::Fup, {vacant()}), 0.0);
}

TEST(ArithLnExp, Values) {
  EXPECT_EQ(call(Builtin::Ln, {1.0}), 0.0);
  EXPECT_NEAR(call(Builtin::Ln, {std::exp(2.0)}), 2.0, 1e-15);
  EXPECT_EQ(call(Builtin::Exp, {0.0}), 1.0);
  EXPECT_EQ(call(Builtin::Exp, {vacant()}), 1.0);
  EXPECT_NEAR(call(Builtin::Exp, {1.0}), 2.718281828459045, 1e-15);
  EXPECT_EQ(call(Builtin::Exp, {-1000.0}), 0.0);
}

TEST(ArithLnExp, Alarms) {
  EXPECT_EQ(callAlarm(Builtin::Ln, {0.0}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Ln, {-1.0}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Ln, {vacant()}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Exp, {710.0}), AlarmId::FloatOverflow);
}

TEST(ArithPow, Values) {
  EXPECT_EQ(call(Builtin::Pow, {2.0, 10.0}), 1024.0);
  EXPECT_EQ(call(Builtin::Pow, {-2.0, 3.0}), -8.0);
  EXPECT_EQ(call(Builtin::Pow, {4.0, 0.5}), 2.0);
  EXPECT_EQ(call(Builtin::Pow, {2.0, -1.0}), 0.5);
  EXPECT_EQ(call(Builtin::Pow, {0.0, 0.0}), 1.0);
  EXPECT_EQ(call(Builtin::Pow, {vacant(), 2.0}), 0.0);
  EXPECT_EQ(call(Builtin::Pow, {3.0, vacant()}), 1.0);
}

TEST(ArithPow, Alarms) {
  EXPECT_EQ(callAlarm(Builtin::Pow, {-2.0, 0.5}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Pow, {0.0, -1.0}), AlarmId::ZeroDivide);
  EXPECT_EQ(callAlarm(Builtin::Pow, {vacant(), -2.0}), AlarmId::ZeroDivide);
  EXPECT_EQ(callAlarm(Builtin::Pow, {10.0, 400.0}), AlarmId::FloatOverflow);
}

TEST(ArithAdp, ReturnsArgument) {
  EXPECT_EQ(call(Builtin::Adp, {0.01}), 0.01);
  EXPECT_EQ(call(Builtin::Adp, {-7.0}), -7.0);
  EXPECT_EQ(call(Builtin::Adp, {vacant()}), 0.0);
}

TEST(ArithBinBcd, Conversions) {
  EXPECT_EQ(call(Builtin::Bin, {37.0}), 25.0); // 0x25
  EXPECT_EQ(call(Builtin::Bin, {0x1234}), 1234.0);
  EXPECT_EQ(call(Builtin::Bin, {0x99999999}), 99999999.0);
  EXPECT_EQ(call(Builtin::Bin, {0.0}), 0.0);
  EXPECT_EQ(call(Builtin::Bin, {36.6}), 25.0); // rounds to 37
  EXPECT_EQ(call(Builtin::Bcd, {25.0}), 37.0);
  EXPECT_EQ(call(Builtin::Bcd, {1234.0}), 0x1234);
  EXPECT_EQ(call(Builtin::Bcd, {99999999.0}), 0x99999999);
  EXPECT_EQ(call(Builtin::Bcd, {24.5}), 37.0); // rounds to 25
  EXPECT_EQ(call(Builtin::Bin, {vacant()}), 0.0);
  EXPECT_EQ(call(Builtin::Bcd, {vacant()}), 0.0);
}

TEST(ArithBinBcd, Alarms) {
  EXPECT_EQ(callAlarm(Builtin::Bin, {0x1A}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Bin, {0xF0}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Bin, {-1.0}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Bin, {0x100000000}),
            AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Bcd, {-1.0}), AlarmId::ArgumentOutOfRange);
  EXPECT_EQ(callAlarm(Builtin::Bcd, {100000000.0}),
            AlarmId::ArgumentOutOfRange);
}

TEST(ArithBuiltinTable, NamesAndArities) {
  EXPECT_STREQ(builtinName(Builtin::Sin), "SIN");
  EXPECT_STREQ(builtinName(Builtin::Atan), "ATAN");
  EXPECT_STREQ(builtinName(Builtin::Atan2), "ATAN");
  EXPECT_STREQ(builtinName(Builtin::Bcd), "BCD");
  EXPECT_EQ(builtinArity(Builtin::Atan), 1);
  EXPECT_EQ(builtinArity(Builtin::Atan2), 2);
  EXPECT_EQ(builtinArity(Builtin::Pow), 2);
  EXPECT_EQ(builtinArity(Builtin::Sqrt), 1);
}

TEST(AlarmTable, InfoAndCodes) {
  EXPECT_EQ(alarmInfo(AlarmId::ZeroDivide).number, 112);
  EXPECT_STREQ(alarmInfo(AlarmId::ZeroDivide).message, "ZERO DIVIDE");
  EXPECT_STREQ(alarmInfo(AlarmId::None).prefix, "");
  EXPECT_EQ(alarmInfo(AlarmId::None).number, 0);
  EXPECT_EQ(alarmCode(AlarmId::ZeroDivide, 0), "PS0112");
  EXPECT_EQ(alarmCode(AlarmId::TooManyDigits, 0), "PS0003");
  EXPECT_EQ(alarmCode(AlarmId::Unsupported, 0), "MBC0001");
  EXPECT_EQ(alarmCode(AlarmId::MacroAlarm, 3001), "3001");
  EXPECT_EQ(alarmCode(AlarmId::None, 0), "");
}

} // namespace
} // namespace mbc

namespace mbc {
namespace {

// Whole-degree results are exact, like SIN[30] = 0.5 (docs/language.md).
TEST(ArithSnap, InverseTrigGivesWholeDegreesExactly) {
  MathParams nat1;
  nat1.nat = true;
  Num out = 0;
  Num half = 0.5, minusHalf = -0.5;
  ASSERT_EQ(evalBuiltin(Builtin::Asin, &half, nat1, &out), AlarmId::None);
  EXPECT_EQ(out, 30.0);
  ASSERT_EQ(evalBuiltin(Builtin::Asin, &minusHalf, nat1, &out), AlarmId::None);
  EXPECT_EQ(out, -30.0);
  ASSERT_EQ(evalBuiltin(Builtin::Acos, &half, nat1, &out), AlarmId::None);
  EXPECT_EQ(out, 60.0);
}

} // namespace
} // namespace mbc
