// Variables through the C ABI: every class of #n, read-only and out-of-range
// alarms, aliases between system variable ranges, the #3000 series and ADP.
#include <cstdlib>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

TEST(RuntimeVariables, LocalsStartVacantAndKeepWrites) {
  Machine m;
  EXPECT_TRUE(isVacant(m.read(1)));
  EXPECT_EQ(m.write(33, 2.5), 0);
  EXPECT_EQ(m.read(33), 2.5);
  EXPECT_EQ(mbrt_current_level(m.ctx())->value[32], 2.5);
}

TEST(RuntimeVariables, NumberIsRoundedHalfAwayFromZero) {
  Machine m;
  EXPECT_EQ(m.write(1.5, 7.0), 0); // #2
  EXPECT_EQ(m.read(2), 7.0);
  EXPECT_EQ(m.read(2.4999), 7.0);
  EXPECT_TRUE(isVacant(m.read(0.4999))); // #0
}

TEST(RuntimeVariables, NullVariableIsVacantAndReadOnly) {
  Machine m;
  EXPECT_TRUE(isVacant(m.read(0)));
  EXPECT_EQ(m.write(0, 1.0), status(AlarmId::WriteProtectedVariable));
  // No block has begun: the write is the host's, and the report says so.
  EXPECT_EQ(m.report(), "alarm PS0116: WRITE PROTECTED VARIABLE: #0 (called "
                        "by the host, outside any block)\n");
}

TEST(RuntimeVariables, GapsBetweenClassesAreOutOfRange) {
  for (double number : {34.0, 99.0, 200.0, 499.0, 1000000.0, -1.0}) {
    Machine m;
    mbrt_num value = 0;
    EXPECT_EQ(mbrt_read_var(m.ctx(), number, &value),
              status(AlarmId::VariableOutOfRange))
        << number;
  }
  Machine m;
  EXPECT_EQ(m.write(34, 1.0), status(AlarmId::VariableOutOfRange));
}

TEST(RuntimeVariables, CommonsAndProfileStartValues) {
  Machine m(R"({"variables": {"500": 1.5, "999": -2}})");
  EXPECT_TRUE(isVacant(m.read(100)));
  EXPECT_EQ(m.read(500), 1.5);
  EXPECT_EQ(m.read(999), -2.0);
  EXPECT_EQ(m.write(199, 3.0), 0);
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_peek_common(m.ctx(), 199, &value), 1);
  EXPECT_EQ(value, 3.0);
  EXPECT_EQ(mbrt_peek_common(m.ctx(), 300, &value), 0);
  EXPECT_EQ(mbrt_peek_common(m.ctx(), 33, &value), 0);
}

TEST(RuntimeVariables, ExtendedCommonsNeedTheProfileOption) {
  Machine m(R"({"extended_common": true})");
  EXPECT_EQ(m.write(200, 4.0), 0);
  EXPECT_EQ(m.read(200), 4.0);
  EXPECT_EQ(m.write(499, 5.0), 0);
}

TEST(RuntimeVariables, InterfaceSignals) {
  Machine m;
  EXPECT_EQ(m.read(1000), 0.0);
  EXPECT_EQ(m.read(1015), 0.0);
  EXPECT_EQ(m.read(1032), 0.0);
  EXPECT_EQ(m.write(1000, 1.0), status(AlarmId::WriteProtectedVariable));
  Machine n;
  EXPECT_EQ(n.write(1032, 1.0), status(AlarmId::WriteProtectedVariable));
  EXPECT_EQ(n.write(1100, 1.0), 0);
  EXPECT_EQ(n.read(1100), 1.0);
  EXPECT_EQ(n.write(1133, 255.0), 0);
  EXPECT_EQ(n.read(1133), 255.0);
  // A 30i-B has 32 single signals each way and four words.
  EXPECT_EQ(n.write(1131, 1.0), 0);
  EXPECT_EQ(n.read(1132), -2147483647.0);
  EXPECT_EQ(n.write(1135, -1.0), 0);
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(n.ctx(), 1036, &value),
            status(AlarmId::VariableOutOfRange));
  EXPECT_EQ(mbrt_read_var(n.ctx(), 1136, &value),
            status(AlarmId::VariableOutOfRange));
}

TEST(RuntimeVariables, ToolOffsetsMemoryC) {
  Machine m(R"({"tool_offsets": {"count": 300,
      "7": {"h_geometry": 100.5, "h_wear": -0.1,
            "d_geometry": 5, "d_wear": 0.02}}})");
  EXPECT_EQ(m.read(10007), -0.1);
  EXPECT_EQ(m.read(2007), -0.1);
  EXPECT_EQ(m.read(11007), 100.5);
  EXPECT_EQ(m.read(2207), 100.5);
  EXPECT_EQ(m.read(13007), 5.0);
  EXPECT_EQ(m.read(12007), 0.02);
  EXPECT_EQ(m.write(2001, 0.5), 0);
  EXPECT_EQ(m.read(10001), 0.5);
  EXPECT_EQ(m.write(11200, 42.0), 0);
  EXPECT_EQ(m.read(2400), 42.0);
  EXPECT_EQ(m.write(13300, 1.0), 0);
  EXPECT_EQ(m.write(13301, 1.0), status(AlarmId::VariableOutOfRange));
}

TEST(RuntimeVariables, MacroAlarmFromVariable3000) {
  Machine m;
  mbrt_begin_block(m.ctx(), "prog.nc", 12);
  EXPECT_EQ(m.write(3000, 1.0, "  X IS MISSING "), status(AlarmId::MacroAlarm));
  EXPECT_EQ(mbrt_alarm(m.ctx()), status(AlarmId::MacroAlarm));
  EXPECT_EQ(m.report(), "prog.nc:12: alarm 3001: X IS MISSING\n");
}

TEST(RuntimeVariables, MacroAlarmMessageIsCutAt26Characters) {
  Machine m;
  mbrt_begin_block(m.ctx(), "prog.nc", 3);
  m.write(3000, 999.0, "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123");
  EXPECT_EQ(m.report(), "prog.nc:3: alarm 3999: ABCDEFGHIJKLMNOPQRSTUVWXYZ\n");
}

TEST(RuntimeVariables, MacroAlarmNumberOutOfRange) {
  Machine m;
  EXPECT_EQ(m.write(3000, 1000.0, "X"), status(AlarmId::ArgumentOutOfRange));
  Machine n;
  EXPECT_EQ(n.write(3000, -1.0, "X"), status(AlarmId::ArgumentOutOfRange));
  EXPECT_EQ(n.read(3000), 0.0);
}

TEST(RuntimeVariables, OperatorMessageGoesOn) {
  Machine m;
  mbrt_begin_block(m.ctx(), "prog.nc", 8);
  EXPECT_EQ(m.write(3006, 1.0, "CHECK TOOL"), 0);
  EXPECT_EQ(m.messages(), "prog.nc:8: message: CHECK TOOL\n");
  EXPECT_EQ(mbrt_alarm(m.ctx()), 0);
}

TEST(RuntimeVariables, ClocksAreSimulated) {
  Machine m;
  EXPECT_EQ(m.read(3001), 0.0);
  // 100 mm at F1000 take 6 s.
  ASSERT_EQ(m.block("G01 X100. F1000."), 0);
  EXPECT_EQ(m.read(3001), 6000.0);
  EXPECT_DOUBLE_EQ(m.read(3002), 0.1 / 60.0);
  // A rapid of 100 mm at the default 10000 mm/min takes 0.6 s.
  ASSERT_EQ(m.block("G00 X0"), 0);
  EXPECT_EQ(m.read(3001), 6600.0);
  EXPECT_EQ(m.write(3001, 5.0), 0);
  EXPECT_EQ(m.read(3001), 5.0);
  EXPECT_EQ(m.write(3002, 2.0), 0);
  EXPECT_EQ(m.read(3002), 2.0);
}

TEST(RuntimeVariables, ControlBits) {
  Machine m;
  EXPECT_EQ(m.write(3003, 3.0), 0);
  EXPECT_EQ(m.read(3003), 3.0);
  EXPECT_EQ(m.write(3004, 7.0), 0);
  EXPECT_EQ(m.read(3004), 7.0);
  EXPECT_EQ(m.write(3005, 12.0), 0);
  EXPECT_EQ(m.read(3005), 12.0);
  EXPECT_EQ(m.read(3007), 0.0);
  EXPECT_EQ(m.write(3004, 8.0), status(AlarmId::ArgumentOutOfRange));
  Machine n;
  EXPECT_EQ(n.write(3003, 4.0), status(AlarmId::ArgumentOutOfRange));
  Machine o;
  EXPECT_EQ(o.write(3007, 1.0), status(AlarmId::WriteProtectedVariable));
}

TEST(RuntimeVariables, DateAndTimeFromSourceDateEpoch) {
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1); // 2023-11-14 22:13:20 UTC
  Machine m;
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_EQ(m.read(3011), 20231114.0);
  EXPECT_EQ(m.read(3012), 221320.0);
  EXPECT_EQ(m.write(3011, 1.0), status(AlarmId::WriteProtectedVariable));
}

TEST(RuntimeVariables, PartsCounters) {
  Machine m(R"({"parts": {"count": 4, "required": 10}})");
  EXPECT_EQ(m.read(3901), 4.0);
  EXPECT_EQ(m.read(3902), 10.0);
  mbrt_finish(m.ctx(), MBRT_END_M02_M30);
  EXPECT_EQ(m.read(3901), 5.0);
  mbrt_finish(m.ctx(), MBRT_END_PROGRAM);
  EXPECT_EQ(m.read(3901), 5.0);
  EXPECT_EQ(m.write(3902, 20.0), 0);
  EXPECT_EQ(m.read(3902), 20.0);
}

TEST(RuntimeVariables, MainProgramNumber) {
  Machine m;
  EXPECT_EQ(m.read(4000), 1000.0);
  EXPECT_EQ(m.read(4115), 1000.0);
  mbrt_start(m.ctx(), "<PART_A>");
  EXPECT_EQ(m.read(4000), 0.0);
  EXPECT_EQ(m.write(4000, 1.0), status(AlarmId::WriteProtectedVariable));
}

TEST(RuntimeVariables, PositionsAreReadOnly) {
  for (double number :
       {4001.0, 4130.0, 4201.0, 4330.0, 5001.0, 5041.0, 5061.0, 5120.0}) {
    Machine m;
    EXPECT_EQ(m.write(number, 1.0), status(AlarmId::WriteProtectedVariable))
        << number;
  }
  Machine m;
  EXPECT_EQ(m.read(5004), 0.0); // beyond the machine's three axes
  EXPECT_EQ(m.read(5101), 0.0);
  EXPECT_EQ(m.read(5121), 0.0); // no manual handle interruption
  EXPECT_EQ(m.write(5121, 1.0), status(AlarmId::WriteProtectedVariable));
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(m.ctx(), 5141, &value),
            status(AlarmId::VariableOutOfRange));
}

// The system constants of a 30i-B: #3100 is vacant as #0 is, #3101 pi,
// #3102 e; none can be written.
TEST(RuntimeVariables, SystemConstants) {
  Machine m;
  EXPECT_TRUE(isVacant(m.read(3100)));
  EXPECT_EQ(m.read(3101), 3.141592653589793);
  EXPECT_EQ(m.read(3102), 2.718281828459045);
  for (double number : {3100.0, 3101.0, 3102.0}) {
    EXPECT_EQ(m.write(number, 1.0), status(AlarmId::WriteProtectedVariable))
        << number;
  }
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(m.ctx(), 3103, &value),
            status(AlarmId::VariableOutOfRange));
}

TEST(RuntimeVariables, WorkOffsetAliases) {
  Machine m(R"({"work_offsets": {"G54.1P2": [1, 2, 3], "G56": [0, 0, -7]}})");
  EXPECT_EQ(m.read(7021), 1.0);
  EXPECT_EQ(m.read(14022), 2.0);
  EXPECT_EQ(m.read(5263), -7.0);
  EXPECT_EQ(m.write(7941, 4.5), 0); // P48 X
  EXPECT_EQ(m.read(14941), 4.5);
  EXPECT_EQ(m.write(19981, 1.25), 0); // P300 X
  EXPECT_EQ(m.read(19981), 1.25);
  EXPECT_EQ(m.read(5204), 0.0); // no fourth axis
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(m.ctx(), 14009, &value),
            status(AlarmId::VariableOutOfRange));
}

TEST(RuntimeVariables, OffsetWritesRoundToTheIncrement) {
  Machine m;
  EXPECT_EQ(m.write(5221, 1.23456), 0);
  EXPECT_EQ(m.read(5221), 1.235);
}

TEST(RuntimeVariables, AdpGivesTheLiteralBack) {
  Machine m;
  ASSERT_EQ(m.callMacro("O9000", "X10 Y10. F10 R5"), 0);
  EXPECT_EQ(m.read(24), 0.010);
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_adp(m.ctx(), 24, &value), 0);
  EXPECT_EQ(value, 10.0);
  EXPECT_EQ(mbrt_adp(m.ctx(), 25, &value), 0);
  EXPECT_EQ(value, 10.0);
  EXPECT_EQ(mbrt_adp(m.ctx(), 9, &value), 0); // F is not scaled
  EXPECT_EQ(value, 10.0);
  EXPECT_EQ(mbrt_adp(m.ctx(), 18, &value), 0);
  EXPECT_EQ(value, 5.0);
  // Any write clears the flag.
  EXPECT_EQ(m.write(24, 0.5), 0);
  EXPECT_EQ(mbrt_adp(m.ctx(), 24, &value), 0);
  EXPECT_EQ(value, 0.5);
  EXPECT_EQ(m.write(100, 0.02), 0);
  EXPECT_EQ(mbrt_adp(m.ctx(), 100, &value), 0);
  EXPECT_EQ(value, 0.02);
}

} // namespace

// The input signals come from the profile and from presets (--set), as the
// PMC would set them; a program only reads them.
TEST(RuntimeVariables, InputSignalsFromProfileAndPresets) {
  Machine m(R"({"input_signals": {"1000": 1, "1033": 255}})");
  EXPECT_EQ(m.read(1000), 1.0);
  EXPECT_EQ(m.read(1001), 0.0);
  EXPECT_EQ(m.read(1032), 1.0);
  EXPECT_EQ(m.read(1033), 255.0);
  ASSERT_EQ(mbrt_preset_var(m.ctx(), 1031, 1.0), 0);
  EXPECT_EQ(m.read(1032), -2147483647.0);
  ASSERT_EQ(mbrt_preset_var(m.ctx(), 1035, -1.0), 0);
  EXPECT_EQ(m.read(1035), -1.0);
  EXPECT_EQ(mbrt_preset_var(m.ctx(), 1002, 0.5),
            status(AlarmId::ArgumentOutOfRange));
  EXPECT_EQ(mbrt_write_var(m.ctx(), 1000, 0.0, nullptr),
            status(AlarmId::WriteProtectedVariable));
}

// Which tool offset a variable reads depends on the offset memory type and
// on 6000#3 V15 (Series 15 numbering: geometry first, D in #2401-#2800).
TEST(RuntimeVariables, ToolOffsetNumberings) {
  Machine standard(R"({"tool_offsets": {"3": {"h_geometry": 120.5,
      "h_wear": -0.02, "d_geometry": 5, "d_wear": 0.01}}})");
  EXPECT_EQ(standard.read(2003), -0.02);
  EXPECT_EQ(standard.read(2203), 120.5);
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(standard.ctx(), 2403, &value),
            status(AlarmId::VariableOutOfRange));
  Machine v15(R"({"parameters": {"6000": 8}, "tool_offsets": {"3":
      {"h_geometry": 120.5, "h_wear": -0.02, "d_geometry": 5,
       "d_wear": 0.01}}})");
  EXPECT_EQ(v15.read(2003), 120.5);
  EXPECT_EQ(v15.read(2203), -0.02);
  EXPECT_EQ(v15.read(2403), 5.0);
  EXPECT_EQ(v15.read(2603), 0.01);
  EXPECT_EQ(v15.read(12003), 5.0);
  Machine b(R"({"tool_offsets": {"memory": "B", "3": {"h_geometry": 120.5,
      "h_wear": -0.02}}})");
  EXPECT_EQ(b.read(10003), -0.02);
  EXPECT_EQ(b.read(11003), 120.5);
  EXPECT_EQ(mbrt_read_var(b.ctx(), 13003, &value),
            status(AlarmId::VariableOutOfRange));
  Machine a(R"({"tool_offsets": {"memory": "A", "3": {"h_geometry": 9.5}}})");
  EXPECT_EQ(a.read(2003), 9.5);
  EXPECT_EQ(a.write(10003, 7.25), 0);
  EXPECT_EQ(a.read(2003), 7.25);
  EXPECT_EQ(mbrt_read_var(a.ctx(), 2203, &value),
            status(AlarmId::VariableOutOfRange));
}

} // namespace mbc::test
