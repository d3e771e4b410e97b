// NC blocks through the C ABI: address conversion, linear moves, units,
// modal information, work offsets, unsupported G codes and the flow asked
// for by M codes.
#include <mbc/g_codes.h>

#include <map>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

/// The block asks for a call of subprogram `program` (M98, M198), `repeat`
/// times.
void expectSubprogramCall(Machine& m, const char* block, int program,
                          long repeat) {
  ASSERT_EQ(m.block(block), 0) << block;
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_CALL) << block;
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_SUB) << block;
  EXPECT_EQ(m.flow().program, program) << block;
  EXPECT_EQ(m.flow().repeat, repeat) << block;
}

TEST(RuntimeNcBlock, AbsoluteAndIncrementalMoves) {
  Machine m;
  ASSERT_EQ(m.block("G90 G00 X10. Y-1.25", 7), 0);
  ASSERT_EQ(m.block("G91 G01 X2.5 Z-1. F200", 8), 0);
  ASSERT_EQ(m.block("X-0.001", 9), 0);
  ASSERT_EQ(m.json().size(), 3u);
  EXPECT_EQ(m.json()[0],
            "{\"motion\":\"rapid\",\"x\":10,\"y\":-1.25,\"z\":0,\"mx\":10,"
            "\"my\":-1.25,\"mz\":0,\"line\":7,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(
      m.json()[1],
      "{\"motion\":\"linear\",\"x\":12.5,\"y\":-1.25,\"z\":-1,\"mx\":12.5,"
      "\"my\":-1.25,\"mz\":-1,\"f\":200,\"line\":8,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(m.motions()[2].end[0], 12.499);
  mbrt_stats stats{};
  mbrt_get_stats(m.ctx(), &stats);
  EXPECT_EQ(stats.moves, 3u);
  EXPECT_EQ(stats.blocks, 3u);
}

// The box holds the points of both input units, in the profile's unit.
TEST(RuntimeNcBlock, TheBoxSpansBothInputUnits) {
  Machine m;
  ASSERT_EQ(m.block("G21 G90 G00 X10. Y-5."), 0);
  ASSERT_EQ(m.block("G20 X1. Y0.5"), 0);
  ASSERT_EQ(m.block("G21 X-3."), 0);
  mbrt_stats stats{};
  mbrt_get_stats(m.ctx(), &stats);
  EXPECT_NEAR(stats.box_min[0], -3.0, 1e-9);
  EXPECT_NEAR(stats.box_max[0], 25.4, 1e-9);
  EXPECT_NEAR(stats.box_min[1], -5.0, 1e-9);
  EXPECT_NEAR(stats.box_max[1], 12.7, 1e-9);
  EXPECT_EQ(stats.box_min[2], 0.0);
  EXPECT_EQ(stats.box_max[2], 0.0);
}

TEST(RuntimeNcBlock, LiteralsWithoutDecimalPointAreIncrements) {
  Machine m;
  ASSERT_EQ(m.block("G01 X10 Y10. F100"), 0);
  EXPECT_EQ(m.motions()[0].end[0], 0.010);
  EXPECT_EQ(m.motions()[0].end[1], 10.0);
  Machine dpi(R"({"parameters": {"3401": 1}})");
  ASSERT_EQ(dpi.block("G01 X10 F100"), 0);
  EXPECT_EQ(dpi.motions()[0].end[0], 10.0);
}

TEST(RuntimeNcBlock, ValuesRoundHalfAwayToTheIncrement) {
  Machine m;
  ASSERT_EQ(m.block("G00 X=1.2345 Y=-1.2345 Z=2.0005"), 0);
  EXPECT_EQ(
      m.json()[0],
      "{\"motion\":\"rapid\",\"x\":1.235,\"y\":-1.235,\"z\":2.001,\"mx\":1.235,"
      "\"my\":-1.235,\"mz\":2.001,\"line\":1,\"prog\":\"O1000\"}\n");
  EXPECT_EQ(m.read(5001), 1.235);
  EXPECT_EQ(m.read(5002), -1.235);
}

TEST(RuntimeNcBlock, IncrementalMovesDoNotDrift) {
  Machine m;
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(m.block("G91 G00 X=0.001"), 0);
  }
  EXPECT_EQ(m.read(5041), 1.0);
}

TEST(RuntimeNcBlock, InchUnits) {
  Machine m(R"({"units": "inch"})");
  ASSERT_EQ(m.block("G00 X1.23456 Y10"), 0);
  EXPECT_EQ(m.motions()[0].decimals, 4);
  EXPECT_EQ(m.motions()[0].end[0], 1.2346);
  EXPECT_EQ(m.motions()[0].end[1], 0.001);
  EXPECT_EQ(m.read(4006), 20.0);
}

TEST(RuntimeNcBlock, SwitchingUnitsConvertsThePosition) {
  Machine m;
  ASSERT_EQ(m.block("G00 X25.4 Y-50.8"), 0);
  ASSERT_EQ(m.block("G20"), 0);
  EXPECT_EQ(m.read(4006), 20.0);
  EXPECT_EQ(m.read(5041), 1.0);
  EXPECT_EQ(m.read(5042), -2.0);
  // The block's own words already read in the new unit.
  ASSERT_EQ(m.block("G21 G91 X1."), 0);
  EXPECT_EQ(m.read(5041), 26.4);
}

TEST(RuntimeNcBlock, FeedZeroAlarm) {
  Machine m;
  EXPECT_EQ(m.block("G01 X10.", 4), status(AlarmId::FeedZero));
  EXPECT_EQ(m.report(), "test.nc:4: alarm PS0011: FEED ZERO (COMMAND FEED): "
                        "G01 needs F greater than 0\n");
  EXPECT_TRUE(m.motions().empty());
  Machine rapid;
  EXPECT_EQ(rapid.block("G00 X10."), 0);
  EXPECT_EQ(rapid.block("G02 X0 R5. F0"), status(AlarmId::FeedZero));
}

// M S T H D take whole numbers of at most 8 digits, F and they no sign
// (spec §1.5).
TEST(RuntimeNcBlock, IntegerAddresses) {
  Machine m;
  EXPECT_EQ(m.block("M3.", 2), status(AlarmId::IllegalDecimalPoint));
  EXPECT_EQ(m.report(), "test.nc:2: alarm PS0007: ILLEGAL USE OF DECIMAL "
                        "POINT: M3.: M takes a whole number\n");
  EXPECT_EQ(Machine().block("T1.5"), status(AlarmId::IllegalDecimalPoint));
  EXPECT_EQ(Machine().block("S-100"), status(AlarmId::IllegalMinusSign));
  EXPECT_EQ(Machine().block("G01 X1. F-10."),
            status(AlarmId::IllegalMinusSign));
  EXPECT_EQ(Machine().block("M100000000"), status(AlarmId::TooManyDigits));
}

// G09 (exact stop, one block) slows down, it does not change the path.
TEST(RuntimeNcBlock, ExactStopMovesAsWritten) {
  Machine m;
  ASSERT_EQ(m.block("G09 G01 X10. F100"), 0);
  EXPECT_EQ(m.read(5001), 10.0);
  EXPECT_EQ(m.read(4001), 1.0);
}

TEST(RuntimeNcBlock, UnsupportedGCodes) {
  Machine m;
  EXPECT_EQ(m.block("G12.1", 3), status(AlarmId::Unsupported));
  EXPECT_EQ(m.report(), "test.nc:3: alarm MBC0001: NOT SUPPORTED BY MBC YET: "
                        "G12.1 (polar coordinate interpolation mode)\n");
  for (const char* block :
       {"G07.1 C20.", "G68 X0 Y0 I0 J0 K1 R45.", "G05 P2", "G60 X1."}) {
    Machine u;
    EXPECT_EQ(u.block(block), status(AlarmId::Unsupported)) << block;
  }
}

// One table says which FANUC G codes mbc executes: mbc check reports the
// others, and the runtime stops at them with MBC0001. Each code here is
// given the words it needs.
TEST(RuntimeNcBlock, TheGCodeTableSaysWhatRuns) {
  const std::map<int, const char*> words = {
      {50, " P0"},        {51, " Q0"},        {54, " Q0"},  {80, " P0"},
      {100, " L2 P1 X0"}, {310, " X1. F100"}, {660, " P1"}, {661, " P1"},
      {680, " R0"},       {541, " P1"}};
  for (int tenths = 0; tenths <= 9999; ++tenths) {
    // G65 never reaches the runtime: the parser makes its block a call.
    if (!isFanucGCode(tenths) || tenths == 650) {
      continue;
    }
    const auto extra = words.find(tenths);
    const std::string block =
        gCodeText(tenths) + (extra != words.end() ? extra->second : "");
    Machine m;
    const bool stopped = m.block(block) == status(AlarmId::Unsupported);
    EXPECT_EQ(stopped, unmodelledGCode(tenths) != nullptr) << block;
  }
}

// Lathe blocks a mill would run silently wrong stop the run, naming the
// lathe form, until there is a lathe profile.
TEST(RuntimeNcBlock, LatheFormsOnAMill) {
  {
    Machine m;
    EXPECT_EQ(m.block("G50 X100. Z0"), status(AlarmId::Unsupported));
    EXPECT_TRUE(m.motions().empty());
    EXPECT_NE(m.report().find("coordinate system setting"), std::string::npos);
  }
  {
    Machine m;
    EXPECT_EQ(m.block("G50 S2000"), status(AlarmId::Unsupported));
    ASSERT_EQ(m.block("G51 X0 Y0 P2."), 0);
    ASSERT_EQ(m.block("G50"), 0); // a mill's scaling cancel
  }
  {
    Machine m;
    EXPECT_EQ(m.block("G01 W-2. F100."), status(AlarmId::ImproperNcAddress));
    EXPECT_NE(m.report().find("on a lathe W is the incremental Z"),
              std::string::npos);
  }
  {
    Machine m;
    EXPECT_EQ(m.block("G99 G01 X10. F0.25"), status(AlarmId::Unsupported));
    EXPECT_NE(m.report().find("G99 F0.25: a lathe's feed per revolution"),
              std::string::npos);
  }
  {
    Machine m;
    EXPECT_EQ(m.block("G01 X10. F0.2"), status(AlarmId::Unsupported));
    EXPECT_NE(m.report().find("F0.2 per minute"), std::string::npos);
  }
  {
    Machine m; // G99 for the canned cycles that follow, F per minute
    ASSERT_EQ(m.block("G99 G81 X10. Z-5. R2. F120."), 0);
    ASSERT_EQ(m.block("G80 G01 X20. F300."), 0);
    ASSERT_EQ(m.block("G95 S1000 G01 X30. F0.2"), 0);
  }
}

// M198 calls like M98 (the program comes from the search path); M98 Q
// starts the program at a sequence number, without P one of the running
// program; G04 P counts milliseconds and takes no decimal point.
TEST(RuntimeNcBlock, CallsThatMustNotBeIgnored) {
  Machine m;
  expectSubprogramCall(m, "M198 P2002 L2", 2002, 2);
  EXPECT_EQ(m.flow().start_seq, 0.0);
  expectSubprogramCall(m, "M98 P2002 Q30", 2002, 1);
  EXPECT_EQ(m.flow().start_seq, 30.0);
  EXPECT_EQ(m.block("M98 P2002 Q0", 4),
            status(AlarmId::SequenceNumberNotFound));
  EXPECT_EQ(m.report(), "test.nc:4: alarm PS0078: SEQUENCE NUMBER NOT FOUND: "
                        "M98 Q0\n");
  expectSubprogramCall(m, "M98 Q30 L2", 1000, 2); // O1000 is running
  EXPECT_EQ(m.flow().start_seq, 30.0);
  Machine anonymous; // a file without O number has none to call
  mbrt_start(anonymous.ctx(), "MAIN");
  EXPECT_EQ(anonymous.block("M98 Q30"), status(AlarmId::Unsupported));
  Machine d;
  EXPECT_EQ(d.block("G04 P1.5", 2), status(AlarmId::IllegalDecimalPoint));
  ASSERT_EQ(d.block("G04 P1500"), 0);
  ASSERT_EQ(d.block("G04 X1.5"), 0);
}

// P and L are numbers and counts: a decimal point is PS0007 wherever they
// are (the manual's addresses with decimal point are the coordinates, F and
// G51's P); a value from a variable is rounded. K is among those addresses:
// a cycle's K2. repeats twice.
TEST(RuntimeNcBlock, NumbersAndCountsTakeNoDecimalPoint) {
  for (const char* block :
       {"M98 P2. L2", "M98 P2 L2.", "G10 L2. P1 X0", "G10 L2 P1. X0",
        "G54.1 P1.", "M99 P10.", "G66 P9010. A1.", "G66.1 P9010 L2."}) {
    Machine m;
    EXPECT_EQ(m.block(block), status(AlarmId::IllegalDecimalPoint)) << block;
  }
  Machine m;
  EXPECT_EQ(m.block("G04 P1000.", 3), status(AlarmId::IllegalDecimalPoint));
  EXPECT_EQ(m.report(), "test.nc:3: alarm PS0007: ILLEGAL USE OF DECIMAL "
                        "POINT: P1000.: P takes a whole number (G04 P counts "
                        "milliseconds; G04 X1.5 is seconds)\n");
  Machine values;
  ASSERT_EQ(values.block("G54.1 P=2.6"), 0);
  EXPECT_EQ(values.read(4130), 3.0);
  ASSERT_EQ(values.block("G51 X0 Y0 P1.5"), 0); // a magnification
  ASSERT_EQ(values.block("G50"), 0);
  ASSERT_EQ(values.block("G91 G81 X10. R1. Z-1. K2. F100."), 0);
  EXPECT_EQ(values.read(5041), 20.0);
}

// Rollover (1008#0 ROA): positions within one turn, G90 the shorter way;
// with 1008#1 RAB the command's sign gives the way. Pure rotary rapids take
// degrees / rapid rate: the clock tells the way taken.
TEST(RuntimeNcBlock, RotaryRollover) {
  Machine shortest(R"({"axes": ["X", "Y", "Z", "A"],
                       "parameters": {"1008": [0, 0, 0, 1]}})");
  ASSERT_EQ(shortest.block("G90 G00 A-150."), 0);
  EXPECT_EQ(shortest.read(5004), 210.0);
  const double before = shortest.read(3001);
  ASSERT_EQ(shortest.block("A540."), 0); // 180: 30 degrees back
  EXPECT_EQ(shortest.read(5004), 180.0);
  EXPECT_NEAR(shortest.read(3001) - before, 30.0 / 10000.0 * 60000.0, 1.0);
  Machine bySign(R"({"axes": ["X", "Y", "Z", "A"],
                     "parameters": {"1008": [0, 0, 0, 3]}})");
  ASSERT_EQ(bySign.block("G90 G00 A-150."), 0);
  const double start = bySign.read(3001);
  ASSERT_EQ(bySign.block("A540."), 0); // 180, the positive way: 330
  EXPECT_EQ(bySign.read(5004), 180.0);
  EXPECT_NEAR(bySign.read(3001) - start, 330.0 / 10000.0 * 60000.0, 1.0);
  Machine none(R"({"axes": ["X", "Y", "Z", "A"]})"); // no rollover
  ASSERT_EQ(none.block("G90 G00 A540."), 0);
  EXPECT_EQ(none.read(5004), 540.0);
}

TEST(RuntimeNcBlock, ReferencePositionNumber) {
  Machine m;
  EXPECT_EQ(m.block("G30 P5 Z0", 6), status(AlarmId::IllegalReferenceReturn));
  EXPECT_EQ(m.report(), "test.nc:6: alarm PS0046: ILLEGAL REFERENCE RETURN "
                        "COMMAND: G30 P5: P must be 2, 3 or 4\n");
  EXPECT_TRUE(m.motions().empty());
}

TEST(RuntimeNcBlock, UnknownGCodes) {
  Machine m;
  EXPECT_EQ(m.block("G7.5", 2), status(AlarmId::ImproperGCode));
  EXPECT_EQ(m.report(), "test.nc:2: alarm PS0010: IMPROPER G-CODE: G7.5\n");
  Machine n;
  EXPECT_EQ(n.block("G100"), status(AlarmId::ImproperGCode));
}

TEST(RuntimeNcBlock, UnknownAddress) {
  Machine m;
  EXPECT_EQ(m.block("G00 A10."), status(AlarmId::ImproperNcAddress));
  EXPECT_NE(m.report().find("A is not an address"), std::string::npos);
  Machine four(R"({"axes": ["X", "Y", "Z", "A"]})");
  EXPECT_EQ(four.block("G00 A10."), 0);
  EXPECT_EQ(four.json()[0],
            "{\"motion\":\"rapid\",\"x\":0,\"y\":0,\"z\":0,\"a\":10,\"mx\":0,"
            "\"my\":0,\"mz\":0,\"ma\":10,\"line\":1,\"prog\":\"O1000\"}\n");
}

TEST(RuntimeNcBlock, TooManyDigits) {
  Machine m;
  EXPECT_EQ(m.block("G00 X=1000000."), status(AlarmId::TooManyDigits));
}

TEST(RuntimeNcBlock, LastGCodeOfAGroupWins) {
  Machine m;
  ASSERT_EQ(m.block("G00 G01 G91 G90 X1. F100"), 0);
  EXPECT_EQ(m.motions()[0].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.read(4001), 1.0);
  EXPECT_EQ(m.read(4003), 90.0);
}

TEST(RuntimeNcBlock, ModalInformation) {
  Machine m;
  EXPECT_EQ(m.read(4001), 0.0);
  EXPECT_EQ(m.read(4002), 17.0);
  EXPECT_EQ(m.read(4003), 90.0);
  EXPECT_EQ(m.read(4005), 94.0);
  EXPECT_EQ(m.read(4006), 21.0);
  EXPECT_EQ(m.read(4007), 40.0);
  EXPECT_EQ(m.read(4008), 49.0);
  EXPECT_EQ(m.read(4009), 80.0);
  EXPECT_EQ(m.read(4010), 98.0);
  EXPECT_EQ(m.read(4012), 67.0);
  EXPECT_EQ(m.read(4014), 54.0);
  EXPECT_EQ(m.read(4018), 50.1);
  EXPECT_EQ(m.read(4030), 0.0);
  ASSERT_EQ(m.block("N20 G03 G18 G91 G99 G55 F150. S1200 T5 M3 H7 D8 B9 E4"),
            0);
  EXPECT_EQ(m.read(4001), 3.0);
  EXPECT_EQ(m.read(4002), 18.0);
  EXPECT_EQ(m.read(4003), 91.0);
  EXPECT_EQ(m.read(4010), 99.0);
  EXPECT_EQ(m.read(4014), 55.0);
  EXPECT_EQ(m.read(4109), 150.0);
  EXPECT_EQ(m.read(4119), 1200.0);
  EXPECT_EQ(m.read(4120), 5.0);
  EXPECT_EQ(m.read(4113), 3.0);
  EXPECT_EQ(m.read(4111), 7.0);
  EXPECT_EQ(m.read(4107), 8.0);
  EXPECT_EQ(m.read(4102), 9.0);
  EXPECT_EQ(m.read(4108), 4.0);
  EXPECT_EQ(m.read(4114), 20.0);
  EXPECT_EQ(m.read(4115), 1000.0);
  EXPECT_EQ(m.read(4319), 1200.0);
  EXPECT_EQ(m.read(4203), 91.0);
}

TEST(RuntimeNcBlock, IntegerAddressesRound) {
  Machine m;
  ASSERT_EQ(m.block("S=1000.5 M=3.4999999 T=2.5"), 0);
  EXPECT_EQ(m.read(4119), 1001.0);
  EXPECT_EQ(m.read(4113), 3.0);
  EXPECT_EQ(m.read(4120), 3.0);
  ASSERT_EQ(m.block("S99999999"), 0); // 8 digits
  EXPECT_EQ(m.read(4119), 99999999.0);
}

TEST(RuntimeNcBlock, BlockEndAndPositions) {
  Machine m;
  ASSERT_EQ(m.block("G01 X10. Y20. Z-3. F100"), 0);
  EXPECT_EQ(m.read(5001), 10.0);
  EXPECT_EQ(m.read(5002), 20.0);
  EXPECT_EQ(m.read(5003), -3.0);
  EXPECT_EQ(m.read(5021), 10.0);
  EXPECT_EQ(m.read(5043), -3.0);
  EXPECT_EQ(m.read(5061), 0.0);
  EXPECT_EQ(m.read(5081), 0.0);
}

TEST(RuntimeNcBlock, WorkOffsetSelection) {
  Machine m(R"({"work_offsets": {"G55": [100, 0, -50], "EXT": [1, 2, 3]}})");
  ASSERT_EQ(m.block("G90 G00 X10. Y10. Z0", 1), 0);
  EXPECT_EQ(m.read(5021), 11.0); // machine = work + G54 (0) + EXT
  ASSERT_EQ(m.block("G55", 2), 0);
  // The machine stays where it is; its workpiece position changes.
  EXPECT_EQ(m.read(5021), 11.0);
  EXPECT_EQ(m.read(5041), -90.0);
  EXPECT_EQ(m.read(5042), 10.0);
  EXPECT_EQ(m.read(5043), 50.0);
  ASSERT_EQ(m.block("G91 G00 X1.", 3), 0);
  EXPECT_EQ(m.json()[1],
            "{\"motion\":\"rapid\",\"x\":-89,\"y\":10,\"z\":50,\"mx\":12,"
            "\"my\":12,\"mz\":3,\"line\":3,\"prog\":\"O1000\"}\n");
  ASSERT_EQ(m.block("G90 G00 X0 Y0 Z0", 4), 0);
  EXPECT_EQ(m.read(5021), 101.0);
  EXPECT_EQ(m.read(5022), 2.0);
  EXPECT_EQ(m.read(5023), -47.0);
}

TEST(RuntimeNcBlock, WritingTheActiveOffsetMovesTheWorkpiecePosition) {
  Machine m;
  ASSERT_EQ(m.block("G55 G00 X10."), 0);
  ASSERT_EQ(m.write(5241, 4.0), 0); // G55 X
  EXPECT_EQ(m.read(5021), 10.0);
  EXPECT_EQ(m.read(5041), 6.0);
  ASSERT_EQ(m.write(5221, 4.0), 0); // G54 X: not active
  EXPECT_EQ(m.read(5041), 6.0);
}

TEST(RuntimeNcBlock, AdditionalWorkOffsets) {
  Machine m(R"({"work_offsets": {"G54.1P7": [5, 0, 0]}})");
  ASSERT_EQ(m.block("G54.1 P7 G00 X1."), 0);
  EXPECT_EQ(m.read(4014), 54.1);
  EXPECT_EQ(m.read(4130), 7.0);
  EXPECT_EQ(m.read(5021), 6.0);
  ASSERT_EQ(m.block("G54.1"), 0); // no P: P1
  EXPECT_EQ(m.read(4130), 1.0);
  EXPECT_EQ(m.read(5041), 6.0);
  Machine n;
  EXPECT_EQ(n.block("G54.1 P301"), status(AlarmId::ImproperNcAddress));
  EXPECT_EQ(n.read(4130), 0.0); // the alarmed block set nothing
  // G54 Pn is another spelling of G54.1 Pn; G54 alone is G54.
  Machine g54(R"({"work_offsets": {"G54.1P7": [5, 0, 0]}})");
  ASSERT_EQ(g54.block("G54 P7 G00 X1."), 0);
  EXPECT_EQ(g54.read(4014), 54.1);
  EXPECT_EQ(g54.read(4130), 7.0);
  EXPECT_EQ(g54.read(5021), 6.0);
  ASSERT_EQ(g54.block("G54"), 0);
  EXPECT_EQ(g54.read(4014), 54.0);
}

TEST(RuntimeNcBlock, SubprogramCallFlow) {
  Machine m;
  expectSubprogramCall(m, "M98 P1234 L3", 1234, 3);
  // 8-digit program numbers (the default): P is the program alone.
  expectSubprogramCall(m, "M98 P50010", 50010, 1);
  expectSubprogramCall(m, "M98 P2000", 2000, 1);
  expectSubprogramCall(m, "M98 P50010 L2", 50010, 2);
  ASSERT_EQ(m.block("M98 P2000 L0"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  EXPECT_EQ(m.block("M98", 6), status(AlarmId::ProgramNotFound));
  EXPECT_EQ(m.report(),
            "test.nc:6: alarm PS0076: PROGRAM NOT FOUND: M98 without P or "
            "Q\n");
}

// With 4-digit program numbers the high digits of a longer P are the
// repeat count when there is no L (spec §5.8); with L, PS0074.
TEST(RuntimeNcBlock, FourDigitSubprogramCall) {
  Machine m(R"({"program_number_digits": 4})");
  expectSubprogramCall(m, "M98 P50010", 10, 5);
  expectSubprogramCall(m, "M98 P10001000", 1000, 1000);
  EXPECT_EQ(m.block("M98 P50010 L2", 7), status(AlarmId::IllegalProgramNumber));
  EXPECT_EQ(m.report(), "test.nc:7: alarm PS0074: ILLEGAL PROGRAM NUMBER: "
                        "O50010: this machine has program numbers O1 to O9999 "
                        "(profile program_number_digits)\n");
}

TEST(RuntimeNcBlock, ReturnAndEndFlow) {
  Machine m;
  ASSERT_EQ(m.block("M99"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_RETURN);
  EXPECT_EQ(m.flow().has_seq, 0);
  ASSERT_EQ(m.block("M99 P20"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_RETURN);
  EXPECT_EQ(m.flow().has_seq, 1);
  EXPECT_EQ(m.flow().seq, 20.0);
  ASSERT_EQ(m.block("M30"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_END);
  EXPECT_EQ(m.flow().counts_part, 1);
  ASSERT_EQ(m.block("M02"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_END);
  ASSERT_EQ(m.block("G00 X1. M05"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
}

TEST(RuntimeNcBlock, MotionComesBeforeTheFlow) {
  Machine m;
  ASSERT_EQ(m.block("G00 X5. M30"), 0);
  EXPECT_EQ(m.motions().size(), 1u);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_END);
}

TEST(RuntimeNcBlock, ProgramStopsGoOn) {
  Machine m;
  ASSERT_EQ(m.block("M00", 5), 0);
  ASSERT_EQ(m.block("M01", 6), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  EXPECT_EQ(m.messages(),
            "test.nc:5: message: M00 program stop (the run goes on)\n"
            "test.nc:6: message: M01 optional stop (the run goes on)\n");
  mbrt_stats stats{};
  mbrt_get_stats(m.ctx(), &stats);
  EXPECT_EQ(stats.optional_stops, 2u);
}

TEST(RuntimeNcBlock, AtMostThreeMCodes) {
  Machine m;
  EXPECT_EQ(m.block("M03 M08 M05"), 0);
  EXPECT_EQ(m.block("M03 M08 M05 M09"), status(AlarmId::ImproperNcAddress));
}

TEST(RuntimeNcBlock, ProgramNameOfTheCurrentLevel) {
  Machine m;
  ASSERT_EQ(m.callMacro("O9100", ""), 0);
  ASSERT_EQ(m.block("G00 X1."), 0);
  EXPECT_STREQ(m.motions()[0].program, "O9100");
  EXPECT_EQ(m.read(4115), 9100.0);
}

TEST(RuntimeNcBlock, ExecutionLimit) {
  Machine m;
  mbrt_set_max_blocks(m.ctx(), 2);
  EXPECT_EQ(m.block("G00 X1.", 1), 0);
  EXPECT_EQ(m.block("G00 X2.", 2), 0);
  EXPECT_EQ(m.block("G00 X3.", 3), status(AlarmId::ExecutionLimit));
  EXPECT_EQ(m.report(), "test.nc:3: alarm MBC0002: EXECUTION LIMIT REACHED: "
                        "more than 2 blocks executed (--max-blocks)\n");
}

TEST(RuntimeNcBlock, AddressIncrements) {
  Machine m;
  EXPECT_EQ(mbrt_address_increment(m.ctx(), 'X'), 0.001);
  EXPECT_EQ(mbrt_address_increment(m.ctx(), 'R'), 0.001);
  EXPECT_EQ(mbrt_address_increment(m.ctx(), 'S'), 1.0);
  EXPECT_EQ(mbrt_address_increment(m.ctx(), 'G'), 0.1);
  Machine inch(R"({"units": "inch"})");
  EXPECT_EQ(mbrt_address_increment(inch.ctx(), 'Y'), 0.0001);
}

} // namespace

TEST(RuntimeNcBlock, ReferenceReturnAndMachineCoordinates) {
  Machine m(R"({"work_offsets": {"G54": [-200, -100, -300]}})");
  ASSERT_EQ(m.block("G90 G00 X10. Y20. Z5."), 0);
  ASSERT_EQ(m.block("G91 G28 Z0"), 0); // through the current point
  EXPECT_EQ(m.read(5023), 0.0);
  EXPECT_EQ(m.read(5043), 300.0);
  ASSERT_EQ(m.block("G90 G28 X0 Y0"), 0); // through X0 Y0
  ASSERT_EQ(m.motions().size(), 4u);
  EXPECT_EQ(m.motions()[2].end[0], 0.0);
  EXPECT_EQ(m.read(5021), 0.0);
  EXPECT_EQ(m.read(5041), 200.0);
  EXPECT_EQ(m.read(5003), 300.0);
  ASSERT_EQ(m.block("G53 Z-50."), 0);
  EXPECT_EQ(m.read(5023), -50.0);
  EXPECT_EQ(m.read(4001), 0.0);          // G28 and G53 are one-shot
  ASSERT_EQ(m.block("G91 G53 Z10."), 0); // ignored in G91
  EXPECT_EQ(m.read(5023), -50.0);
}

// G05, G05.1, G05.4 and G08 switch look-ahead and smoothing: nothing moves,
// the words are checked, and smoothing says that the path is the programmed
// one.
TEST(RuntimeNcBlock, LookAheadSwitches) {
  Machine m;
  for (const char* block : {"G05.1 Q1 R5", "G05.1 Q0", "G08 P1", "G08 P0",
                            "G05 P10000", "G05 P0", "G05.4 Q1", "G05.4 Q0"}) {
    EXPECT_EQ(m.block(block), 0) << block;
  }
  ASSERT_EQ(m.block("G05.1 Q3 X0 Y0 Z0", 4), 0);
  EXPECT_TRUE(m.motions().empty());
  EXPECT_EQ(m.messages(),
            "test.nc:4: message: G05.1 Q3 nano smoothing: the toolpath keeps "
            "the programmed points (the control smooths between them within "
            "its tolerance)\n");
  EXPECT_EQ(m.block("G08 P2", 5), status(AlarmId::ImproperNcAddress));
  EXPECT_EQ(m.report(), "test.nc:5: alarm PS0009: IMPROPER NC-ADDRESS: G8 "
                        "P2: P takes 0 or 1\n");
}

TEST(RuntimeNcBlock, HighSpeedCycleMachiningIsNotModelled) {
  Machine m;
  EXPECT_EQ(m.block("G05 P3", 2), status(AlarmId::Unsupported));
  EXPECT_EQ(m.report(), "test.nc:2: alarm MBC0001: NOT SUPPORTED BY MBC YET: "
                        "G05 P3 (high-speed cycle machining)\n");
}

} // namespace mbc::test
