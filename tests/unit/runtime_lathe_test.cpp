// The T series (lathe) profile: G code systems A, B and C, diameter
// programming, U/W, G50, constant surface speed and the clock of feeds per
// revolution and threads. Expected times are derived by hand in comments.
#include <cmath>
#include <numbers>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kLathe = R"({"series": "T"})";
constexpr const char* kSystemB =
    R"({"series": "T", "parameters": {"3401": 64}})";
constexpr const char* kSystemC =
    R"({"series": "T", "parameters": {"3401": 128}})";

bool reports(const Machine& m, std::string_view text) {
  return m.report().find(text) != std::string::npos;
}

TEST(RuntimeLathe, ProfileKeys) {
  EXPECT_EQ(profileError(R"({"series": "T"})"), "");
  EXPECT_EQ(profileError(R"({"series": "T", "axes": ["X", "Z", "C"]})"), "");
  EXPECT_NE(profileError(R"({"series": "L"})").find("\"series\" must be"),
            std::string::npos);
  EXPECT_NE(profileError(R"({"series": "T", "axes": ["X", "Y"]})")
                .find("must name X and Z on a lathe"),
            std::string::npos);
  EXPECT_NE(profileError(R"({"series": "T", "parameters": {"3401": 192}})")
                .find("GSB"),
            std::string::npos);
}

TEST(RuntimeLathe, PowerOnState) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G00 X20. Z1."), 0);
  EXPECT_STREQ(m.motions()[0].axis_names, "XZ");
  EXPECT_EQ(m.read(4016), 18.0); // G18
  EXPECT_EQ(m.read(4005), 99.0); // feed per revolution, system A
  EXPECT_EQ(m.read(4002), 97.0);
  EXPECT_EQ(m.read(4003), 0.0); // system A has no G90/G91
  Machine fpm(R"({"series": "T", "parameters": {"3402": 16}})");
  EXPECT_EQ(fpm.read(4005), 98.0); // 3402#4 FPM
}

TEST(RuntimeLathe, DiameterWordsReadAndShowDiameters) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G00 X40.001 Z10."), 0);
  EXPECT_EQ(m.read(5001), 40.001); // half an increment of radius, exact
  EXPECT_EQ(m.motions()[0].end[0], 40.001);
  ASSERT_EQ(m.block("G00 X40001 Z10"), 0); // increments: 40.001, 0.010
  EXPECT_EQ(m.read(5001), 40.001);
  EXPECT_EQ(m.read(5002), 0.01);
  ASSERT_EQ(m.block("G00 Z10.0004"), 0); // rounded to the increment
  EXPECT_EQ(m.read(5002), 10.0);
  ASSERT_EQ(m.block("G01 U-10. W-5. F0.2 S500"), 0);
  EXPECT_EQ(m.read(5001), 30.001);
  EXPECT_EQ(m.read(5002), 5.0);
  // One block with X and U: the later word counts.
  ASSERT_EQ(m.block("G00 X10. U4."), 0);
  EXPECT_EQ(m.read(5001), 34.001);
  ASSERT_EQ(m.block("G00 U4. X10."), 0);
  EXPECT_EQ(m.read(5001), 10.0);
}

// The feed of an arc follows its true (radius) geometry; I is a radius.
TEST(RuntimeLathe, ArcsUseRadii) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G98 G00 X0 Z0"), 0);
  // From radius 0 to radius 10 about (r 10, z 0): a quarter circle of
  // radius 10, 15.708 mm at F100: 9.4248 s.
  ASSERT_EQ(m.block("G02 X20. Z-10. I10. K0 F100."), 0);
  const mbrt_motion& arc = m.motions()[1];
  EXPECT_EQ(arc.end[0], 20.0);
  EXPECT_EQ(arc.center_axes[0], 'Z');
  EXPECT_EQ(arc.center[0], 0.0);
  EXPECT_EQ(arc.center[1], 20.0); // shown as a diameter, like X
  EXPECT_EQ(m.read(3001), std::floor(5.0 * std::numbers::pi / 100.0 * 60000.0));
  // R is a radius too: X20 Z-10 to X40 Z-20 with R10, another quarter.
  ASSERT_EQ(m.block("G03 X40. Z-20. R10."), 0);
  EXPECT_EQ(m.read(3001),
            std::floor(10.0 * std::numbers::pi / 100.0 * 60000.0));
}

TEST(RuntimeLathe, CoordinateSettingAndSpindleLimit) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G50 X200. Z100."), 0);
  EXPECT_TRUE(m.motions().empty());
  EXPECT_EQ(m.read(5041), 200.0);
  EXPECT_EQ(m.read(5042), 100.0);
  ASSERT_EQ(m.block("G00 U-20."), 0);
  EXPECT_EQ(m.read(5001), 180.0);
  EXPECT_EQ(m.read(5021), -20.0); // the machine moved 10 mm of radius
  ASSERT_EQ(m.block("S800 M03"), 0);
  ASSERT_EQ(m.block("G50 S2000"), 0); // a limit, not a speed
  EXPECT_EQ(m.read(4119), 800.0);
}

// Feed per revolution in G97: F0.2 at 1000 rpm is 200 mm/min: 10 mm take
// 3 s.
TEST(RuntimeLathe, FeedPerRevolution) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S1000 M03"), 0);
  ASSERT_EQ(m.block("G00 X20. Z0"), 0);
  const double before = m.read(3001);
  ASSERT_EQ(m.block("G01 W-10. F0.2"), 0);
  EXPECT_NEAR(m.read(3001) - before, 3000.0, 1.0);
  Machine stopped(kLathe);
  ASSERT_EQ(stopped.block("G00 X20. Z0"), 0);
  EXPECT_EQ(stopped.block("G01 W-10. F0.2"), status(AlarmId::FeedZero));
  EXPECT_TRUE(reports(stopped, "feed per revolution (G99) needs a spindle"));
}

// G34 from Z0 to Z-30 at 600 rpm, lead F2 growing by K0.1 per
// revolution: 2 n + 0.05 n^2 = 30 gives n = (sqrt(10) - 2) / 0.1 =
// 11.6228 revolutions, 1.16228 s (G32 would take 15: 1.5 s). The lead
// shrinking by K-0.1 reaches 0 after 20 mm (4 - 0.2 L = 0): PS0014.
TEST(RuntimeLathe, VariableLeadThreading) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S600 M03 G00 X20. Z0"), 0);
  const double before = m.read(3001);
  ASSERT_EQ(m.block("G34 Z-30. F2. K0.1"), 0);
  EXPECT_NEAR(m.read(3001) - before, (std::sqrt(10.0) - 2.0) / 0.1 * 100.0,
              1.0);
  EXPECT_EQ(m.read(4001), 34.0);
  EXPECT_EQ(m.motions().back().feed, 2.0);
  ASSERT_EQ(m.block("G00 Z0"), 0);
  const double back = m.read(3001);
  ASSERT_EQ(m.block("G34 Z-30. F2."), 0); // no K: a constant lead, as G32
  EXPECT_NEAR(m.read(3001) - back, 1500.0, 1.0);
  ASSERT_EQ(m.block("G00 Z0"), 0);
  EXPECT_EQ(m.block("G34 Z-30. F2. K-0.1"),
            status(AlarmId::IllegalLeadCommand));
  ASSERT_EQ(m.block("G34 Z-19. F2. K-0.1"), 0);
}

// G96 facing from X100 to X0 at 200 m/min, limited to 2000 rpm, F0.2 per
// revolution. A revolution takes 2 pi r / 200000 min at radius r mm; the
// limit holds below rc = 200000 / (2 pi 2000) = 15.9155 mm, where it takes
// 1/2000 min. Time = (1/F) [pi (50^2 - rc^2) / 200000 + rc / 2000]
// = 5 (0.0352913 + 0.0079577) min = 12.9747 s.
TEST(RuntimeLathe, ConstantSurfaceSpeedFacing) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G50 S2000"), 0);
  ASSERT_EQ(m.block("G00 X100. Z0"), 0);
  const double before = m.read(3001);
  ASSERT_EQ(m.block("G96 S200 M03"), 0);
  ASSERT_EQ(m.block("G01 X0 F0.2"), 0);
  const double rc = 200000.0 / (2.0 * std::numbers::pi * 2000.0);
  const double minutes =
      5.0 * (std::numbers::pi * (2500.0 - rc * rc) / 200000.0 + rc / 2000.0);
  EXPECT_NEAR(m.read(3001) - before, minutes * 60000.0, 1.0);
  // Without a limit the speed rises to the centre: the mean time of a
  // revolution is pi 50 / 200000 min over the 50 mm: 5 pi 2500 / 200000.
  Machine free(kLathe);
  ASSERT_EQ(free.block("G00 X100. Z0"), 0);
  const double start = free.read(3001);
  ASSERT_EQ(free.block("G96 S200 G01 X0 F0.2"), 0);
  EXPECT_NEAR(free.read(3001) - start,
              5.0 * std::numbers::pi * 2500.0 / 200000.0 * 60000.0, 1.0);
}

// G32: F is the lead per revolution along the longer axis: 30 mm of Z at
// 2 mm and 500 rpm take 30 / 1000 min = 1.8 s, taper or not, G98 or G99.
TEST(RuntimeLathe, ThreadingLead) {
  for (const char* mode : {"G99", "G98"}) {
    Machine m(kLathe);
    ASSERT_EQ(m.block(std::string(mode) + " G97 S500 M03"), 0);
    ASSERT_EQ(m.block("G00 X30. Z5."), 0);
    double before = m.read(3001);
    ASSERT_EQ(m.block("G32 W-30. F2."), 0);
    EXPECT_NEAR(m.read(3001) - before, 1800.0, 1.0) << mode;
    EXPECT_EQ(m.read(4001), 32.0);
    ASSERT_EQ(m.block("G00 U10. W30."), 0);
    before = m.read(3001);
    ASSERT_EQ(m.block("G32 U-10. W-30. F2."), 0);
    EXPECT_NEAR(m.read(3001) - before, 1800.0, 1.0) << mode;
  }
}

TEST(RuntimeLathe, DwellWords) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G04 U1.5"), 0);
  EXPECT_EQ(m.read(3001), 1500.0);
  ASSERT_EQ(m.block("G04 X2."), 0);
  ASSERT_EQ(m.block("G04 P500"), 0);
  EXPECT_EQ(m.read(3001), 4000.0);
  EXPECT_TRUE(m.motions().empty());
}

TEST(RuntimeLathe, SystemBAndC) {
  Machine b(kSystemB);
  EXPECT_EQ(b.read(4005), 95.0);
  EXPECT_EQ(b.read(4003), 90.0);
  ASSERT_EQ(b.block("G92 X100. Z50. S1500"), 0); // system B's G50
  EXPECT_EQ(b.read(5041), 100.0);
  ASSERT_EQ(b.block("G91 G00 X-20."), 0);
  EXPECT_EQ(b.read(5001), 80.0);
  ASSERT_EQ(b.block("G94 G90"), 0);
  EXPECT_EQ(b.read(4005), 94.0);
  ASSERT_EQ(b.block("S600 G33 Z20. F1.5"), 0);
  EXPECT_EQ(b.read(4001), 33.0);
  EXPECT_EQ(b.block("G00 U5."), status(AlarmId::ImproperNcAddress));
  EXPECT_TRUE(reports(b, "in system B write G91 X"));
  Machine c(kSystemC);
  ASSERT_EQ(c.block("G70"), 0); // inch in system C
  EXPECT_EQ(c.read(4006), 70.0);
}

// H is the incremental C of G code system A: it moves a C axis, and where
// there is none (or in systems B and C, which write G91 C) it is no address,
// never a mill's H offset.
TEST(RuntimeLathe, HIsTheIncrementalC) {
  Machine c(R"({"series": "T", "axes": ["X", "Z", "C"]})");
  ASSERT_EQ(c.block("G98 G00 X50. Z2. C10."), 0);
  ASSERT_EQ(c.block("G01 H90. F100."), 0);
  EXPECT_EQ(c.motions().back().end[2], 100.0);
  Machine none(kLathe);
  EXPECT_EQ(none.block("G01 H90. F100."), status(AlarmId::ImproperNcAddress));
  EXPECT_TRUE(reports(none, "the profile has no C axis"));
  Machine b(R"({"series": "T", "axes": ["X", "Z", "C"],
      "parameters": {"3401": 64}})");
  EXPECT_EQ(b.block("G01 H90. F100."), status(AlarmId::ImproperNcAddress));
  EXPECT_TRUE(reports(b, "in system B write G91 C"));
}

TEST(RuntimeLathe, CodesNotModelledYetStopTheRun) {
  const std::pair<const char*, const char*> cases[] = {
      {"G07.1 C20.", "G7.1 (cylindrical interpolation)"},
      {"G12.1", "G12.1 (polar coordinate interpolation mode)"},
  };
  for (const auto& [block, text] : cases) {
    Machine m(kLathe);
    EXPECT_EQ(m.block(block), status(AlarmId::Unsupported)) << block;
    EXPECT_TRUE(reports(m, text)) << m.report();
  }
  Machine a(kLathe);
  EXPECT_EQ(a.block("G91 U1."), status(AlarmId::ImproperGCode));
  Machine b(kSystemB);
  EXPECT_EQ(b.block("G12.1"), status(AlarmId::Unsupported));
  EXPECT_TRUE(reports(b, "G12.1 (polar coordinate interpolation mode)"));
  Machine mill;
  EXPECT_EQ(mill.block("G43 H1"), 0);
  Machine lathe(kLathe);
  EXPECT_EQ(lathe.block("G43 H1"), status(AlarmId::ImproperGCode));
}

constexpr const char* kOffsets = R"({"series": "T", "tool_offsets": {
  "1": {"x_geometry": -250, "z_geometry": -400, "x_wear": 0.04,
        "z_wear": -0.02, "r_geometry": 0.8, "tip": 3}}})";

// The geometry offset shifts the coordinates (the tool stays); the wear
// offset moves the tool in the T code's block.
TEST(RuntimeLatheOffsets, TCodeShiftsAndMoves) {
  Machine m(kOffsets);
  ASSERT_EQ(m.block("T0101"), 0);
  ASSERT_EQ(m.motions().size(), 1U); // the wear: 0.04 of diameter, -0.02
  EXPECT_EQ(m.motions()[0].kind, MBRT_MOTION_RAPID);
  EXPECT_NEAR(m.motions()[0].machine[0], 0.04, 1e-12);
  EXPECT_NEAR(m.motions()[0].machine[1], -0.02, 1e-12);
  EXPECT_EQ(m.read(5001), 250.0); // the tool tip, geometry shifted
  EXPECT_EQ(m.read(5002), 400.0);
  EXPECT_NEAR(m.read(5081), -249.96, 1e-9);
  ASSERT_EQ(m.block("G00 X50. Z2."), 0);
  EXPECT_NEAR(m.motions()[1].machine[0], 50.0 - 250.0 + 0.04, 1e-9);
  EXPECT_NEAR(m.motions()[1].machine[1], 2.0 - 400.0 - 0.02, 1e-9);
  EXPECT_EQ(m.motions()[1].end[0], 50.0);
  // T0100 takes the wear back off; the geometry offset stays (5002#5 LGC).
  ASSERT_EQ(m.block("T0100"), 0);
  EXPECT_NEAR(m.motions()[2].machine[0], 50.0 - 250.0, 1e-9);
  EXPECT_EQ(m.read(5001), 50.0);
  EXPECT_NEAR(m.read(5081), -250.0, 1e-9);
}

// G20 re-expresses the offset in force in inches, as the mill's G43
// length: -10 + 0.2 mm of diameter is -0.3858 inch, not the -0.98 of
// counts left in 0.001 mm.
TEST(RuntimeLatheOffsets, UnitSwitchKeepsTheOffsetInForce) {
  Machine m(R"({"series": "T", "tool_offsets": {
    "3": {"x_geometry": -10, "x_wear": 0.2, "z_geometry": 5}}})");
  blocks(m, {"G00 X100. Z50. T0303", "G20", "G00 X2. Z1."});
  EXPECT_NEAR(m.read(5081), -0.3858, 1e-9);
  EXPECT_NEAR(m.read(5082), 5.0 / 25.4, 0.00005); // in half increments
  const mbrt_motion& move = m.motions().back();
  EXPECT_EQ(move.end[0], 2.0);
  EXPECT_NEAR(move.machine[0], 2.0 - 0.3858, 1e-9);
  EXPECT_NEAR(move.machine[1], 1.0 + 5.0 / 25.4, 0.00005);
}

TEST(RuntimeLatheOffsets, Variables) {
  Machine m(kOffsets);
  EXPECT_EQ(m.read(2001), 0.04);
  EXPECT_EQ(m.read(10001), 0.04);
  EXPECT_EQ(m.read(2101), -0.02);
  EXPECT_EQ(m.read(2701), -250.0);
  EXPECT_EQ(m.read(15001), -250.0);
  EXPECT_EQ(m.read(16001), -400.0);
  EXPECT_EQ(m.read(2901), 0.8);
  EXPECT_EQ(m.read(17001), 0.8);
  EXPECT_EQ(m.read(2301), 3.0);
  EXPECT_EQ(m.read(13001), 3.0);
  EXPECT_EQ(m.read(2264), 0.0);
  ASSERT_EQ(m.write(2001, 0.1), 0);
  EXPECT_EQ(m.read(10001), 0.1);
  ASSERT_EQ(m.write(12002, 0.40004), 0); // rounded to the increment
  EXPECT_EQ(m.read(2202), 0.4);
  mbrt_num value = 0;
  for (const double n : {2065.0, 2401.0, 14001.0, 10065.0, 18001.0}) {
    EXPECT_EQ(mbrt_read_var(m.ctx(), n, &value),
              status(AlarmId::VariableOutOfRange))
        << n;
  }
  EXPECT_EQ(m.write(2301, 10.0), status(AlarmId::ArgumentOutOfRange));
  Machine y(R"({"series": "T", "axes": ["X", "Y", "Z"]})");
  EXPECT_EQ(y.read(2401), 0.0);
  EXPECT_EQ(y.read(19001), 0.0);
  Machine combined(
      R"({"series": "T", "tool_offsets": {"geometry_wear": false}})");
  EXPECT_EQ(mbrt_read_var(combined.ctx(), 2701, &value),
            status(AlarmId::VariableOutOfRange));
  EXPECT_TRUE(reports(combined, "geometry offsets need"));
  Machine mill;
  EXPECT_EQ(mbrt_read_var(mill.ctx(), 2801, &value),
            status(AlarmId::VariableOutOfRange));
  EXPECT_TRUE(reports(mill, "a lathe's tool offset"));
}

TEST(RuntimeLatheOffsets, G10WritesOffsets) {
  Machine m(kOffsets);
  ASSERT_EQ(m.block("G10 P10002 X-200. Z-300. R0.4 Q2"), 0);
  ASSERT_EQ(m.block("G10 P2 X0.1 W-0.05"), 0);
  ASSERT_EQ(m.block("G10 P2 U0.02 W-0.01 C0.1"), 0);
  EXPECT_TRUE(m.motions().empty());
  EXPECT_EQ(m.read(2702), -200.0);
  EXPECT_EQ(m.read(2802), -300.0);
  EXPECT_EQ(m.read(2902), 0.4);
  EXPECT_EQ(m.read(2302), 2.0);
  EXPECT_NEAR(m.read(2002), 0.12, 1e-12);
  EXPECT_NEAR(m.read(2102), -0.06, 1e-12);
  EXPECT_NEAR(m.read(2202), 0.1, 1e-12);
  ASSERT_EQ(m.block("G10 P1 X200"), 0); // increments: 0.2
  EXPECT_NEAR(m.read(2001), 0.2, 1e-12);
  EXPECT_EQ(m.block("G10 P65 X0"), status(AlarmId::IllegalPInG10));
  EXPECT_EQ(m.block("T0165"), status(AlarmId::IllegalOffsetNumber));
  Machine combined(
      R"({"series": "T", "tool_offsets": {"geometry_wear": false}})");
  EXPECT_EQ(combined.block("G10 P10001 X1."), status(AlarmId::IllegalPInG10));
  ASSERT_EQ(combined.block("G10 P1 X-100. Z-50."), 0);
  ASSERT_EQ(combined.block("T0101"), 0);
  EXPECT_NEAR(combined.motions()[0].machine[0], -100.0, 1e-9);
}

// G10 L2 (and L20) write work offsets on a lathe too, not tool offset P:
// G54 Z-300 puts program Z2 at machine Z-298; W adds in system A; P0 is the
// external offset, which adds to every work coordinate system.
TEST(RuntimeLatheOffsets, G10L2WritesWorkOffsets) {
  Machine m(kOffsets);
  ASSERT_EQ(m.block("G10 L2 P1 X0 Z-300."), 0);
  ASSERT_EQ(m.block("G10 L2 P1 W2."), 0);
  ASSERT_EQ(m.block("G10 L2 P0 Z-1."), 0);
  EXPECT_EQ(m.read(2101), -0.02); // the profile's, not written
  EXPECT_EQ(m.read(5222), -298.0);
  EXPECT_EQ(m.read(5202), -1.0);
  ASSERT_EQ(m.block("G54 G00 X20. Z2."), 0);
  ASSERT_EQ(m.motions().size(), 1U);
  EXPECT_NEAR(m.motions()[0].machine[1], -297.0, 1e-9);
  EXPECT_NEAR(m.motions()[0].end[1], 2.0, 1e-9);
  EXPECT_EQ(m.block("G10 L2 P7 Z0"), status(AlarmId::IllegalPInG10));
}

// G90 from A (X52 Z2): rapid to the cut's X, feed to the end, feed out in
// X, rapid back; X alone repeats with the same Z; R tapers (the cut starts
// at X + 2R).
TEST(RuntimeLatheCycles, OuterDiameterCycle) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S1000 G00 X52. Z2."), 0);
  ASSERT_EQ(m.block("G90 X45. Z-30. F0.25"), 0);
  ASSERT_EQ(m.block("X40."), 0);
  EXPECT_EQ(ends(m, 1), (Points{{45, 2},
                                {45, -30},
                                {52, -30},
                                {52, 2},
                                {40, 2},
                                {40, -30},
                                {52, -30},
                                {52, 2}}));
  EXPECT_EQ(m.motions()[1].kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions()[2].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[3].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[4].kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions()[2].cycle, 90);
  EXPECT_EQ(m.read(4001), 90.0);
  EXPECT_EQ(m.read(5001), 52.0); // back at A
  ASSERT_EQ(m.block("G90 X40. Z-30. R-2.5"), 0);
  EXPECT_EQ(ends(m, 9)[0], std::make_pair(35.0, 2.0));
  EXPECT_EQ(ends(m, 9)[1], std::make_pair(40.0, -30.0));
  ASSERT_EQ(m.block("G00 X60."), 0); // G00 ends the cycle
  EXPECT_EQ(m.read(4001), 0.0);
  Machine b(kSystemB);
  ASSERT_EQ(b.block("G95 S1000 G00 X52. Z2."), 0);
  ASSERT_EQ(b.block("G77 X45. Z-30. F0.25"), 0);
  EXPECT_EQ(b.motions()[2].cycle, 77);
  EXPECT_EQ(b.read(4001), 77.0);
}

// G94 faces: rapid in Z, feed in X, feed back in Z, rapid back in X. G92
// threads with rapid returns; its time follows the lead: 25 mm at 1.5 mm
// and 1000 rpm take 1 s.
TEST(RuntimeLatheCycles, FaceAndThreadCycles) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S1000 G00 X52. Z2."), 0);
  ASSERT_EQ(m.block("G94 X20. Z-2. F0.2"), 0);
  EXPECT_EQ(ends(m, 1), (Points{{52, -2}, {20, -2}, {20, 2}, {52, 2}}));
  ASSERT_EQ(m.block("G00 X25. Z5."), 0);
  ASSERT_EQ(m.block("G92 X19.3 Z-20. F1.5"), 0);
  EXPECT_EQ(ends(m, 6), (Points{{19.3, 5}, {19.3, -20}, {25, -20}, {25, 5}}));
  EXPECT_EQ(m.motions()[8].kind, MBRT_MOTION_RAPID);
  const double before = m.read(3001);
  ASSERT_EQ(m.block("G98 X18.9"), 0);
  // In 3.05 and out 3.05 of radius, back 25 along Z, at 10 m/min.
  const double rapids = (3.05 + 3.05 + 25.0) / 10000.0 * 60000.0;
  EXPECT_NEAR(m.read(3001) - before, 1000.0 + rapids, 1.0);
}

// G74 on the centre: pecks of 5 mm backing out 1 mm, then back to A.
TEST(RuntimeLatheCycles, FacePeckDrilling) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S800 G00 X0 Z2."), 0);
  ASSERT_EQ(m.block("G74 R1."), 0);
  ASSERT_EQ(m.block("G74 Z-20. Q5000 F0.1"), 0);
  EXPECT_EQ(ends(m, 1), (Points{{0, -3},
                                {0, -2},
                                {0, -8},
                                {0, -7},
                                {0, -13},
                                {0, -12},
                                {0, -18},
                                {0, -17},
                                {0, -20},
                                {0, 2}}));
  EXPECT_EQ(m.motions()[1].cycle, 74);
}

// G75: columns 1.5 mm apart in Z, pecks of 1.5 mm of radius (3 of
// diameter) in X backing out 0.3, then rapid out and across.
TEST(RuntimeLatheCycles, Grooving) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S600 G00 X26. Z-24."), 0);
  ASSERT_EQ(m.block("G75 R0.3"), 0);
  ASSERT_EQ(m.block("G75 X20. Z-25.5 P1500 Q1500 F0.06"), 0);
  EXPECT_EQ(ends(m, 1), (Points{{23, -24},
                                {23.6, -24},
                                {20, -24},
                                {26, -24},
                                {26, -25.5},
                                {23, -25.5},
                                {23.6, -25.5},
                                {20, -25.5},
                                {26, -25.5},
                                {26, -24}}));
  EXPECT_EQ(m.block("G75 X20. Z-30. P0 Q1500 F0.06"),
            status(AlarmId::IllegalRepetitiveCycle));
}

// G76 M20x2.5: k 1.534, first depth 0.5, least 0.1, allowance 0.05, one
// finishing pass, no chamfer, 60 degrees: depths 0.5 sqrt(n), but at least
// 0.1 deeper each pass (the 7th and 8th), up to 1.484, then 1.534; each
// pass starts depth x tan 30 towards the thread's end.
TEST(RuntimeLatheCycles, MultipleThreading) {
  Machine m(kLathe);
  ASSERT_EQ(m.block("G97 S500 G00 X24. Z5."), 0);
  ASSERT_EQ(m.block("G76 P010060 Q100 R0.05"), 0);
  ASSERT_EQ(m.block("G76 X16.933 Z-30. P1534 Q500 F2.5"), 0);
  const double depths[] = {0.5,
                           0.5 * std::sqrt(2.0),
                           0.5 * std::sqrt(3.0),
                           1.0,
                           0.5 * std::sqrt(5.0),
                           0.5 * std::sqrt(6.0),
                           0.5 * std::sqrt(6.0) + 0.1,
                           0.5 * std::sqrt(6.0) + 0.2,
                           1.484,
                           1.534};
  ASSERT_EQ(m.motions().size(), 1 + 4 * std::size(depths));
  const double flank = std::tan(std::numbers::pi / 6.0);
  for (std::size_t i = 0; i < std::size(depths); ++i) {
    const mbrt_motion& in = m.motions()[1 + 4 * i];
    const mbrt_motion& thread = m.motions()[2 + 4 * i];
    EXPECT_NEAR(in.end[0], 16.933 + 2.0 * (1.534 - depths[i]), 0.0011) << i;
    EXPECT_NEAR(in.end[1], 5.0 - depths[i] * flank, 0.0011) << i;
    EXPECT_EQ(thread.end[1], -30.0);
    EXPECT_EQ(thread.kind, MBRT_MOTION_LINEAR);
    EXPECT_EQ(m.motions()[3 + 4 * i].end[0], 24.0);
    EXPECT_EQ(m.motions()[4 + 4 * i].end[1], 5.0);
  }
  EXPECT_EQ(m.block("G76 X16.933 Z-30. P0 Q500 F2.5"),
            status(AlarmId::IllegalRepetitiveCycle));
  // r = 10: a pull-out over one lead (2.5) in Z, rising at 60 degrees
  // (5131): 2.5 tan 60 = 4.330 of radius.
  Machine pull(R"({"series": "T", "parameters": {"5131": 60}})");
  ASSERT_EQ(pull.block("G97 S500 G00 X24. Z5."), 0);
  ASSERT_EQ(pull.block("G76 P011060 Q100 R0.05"), 0);
  ASSERT_EQ(pull.block("G76 X16.933 Z-30. P1534 Q500 F2.5"), 0);
  EXPECT_EQ(pull.motions()[2].end[1], -27.5);
  EXPECT_NEAR(pull.motions()[3].end[0],
              pull.motions()[2].end[0] + 2.0 * 2.5 * std::sqrt(3.0), 0.0011);
  EXPECT_EQ(pull.motions()[3].end[1], -30.0);
}

/// Points equal but for the last bits of arithmetic (or, with
/// `tolerance`, within the counts of a computed path).
// G71 type I, OD: from A (X60 Z2) cuts 2 mm deep (X56, 52, ... 32), each
// from Z2 to the shape shifted by the allowance (0.4 of diameter, 0.1 in
// Z), escaping 0.5 at 45 degrees; then along the shifted shape and back to
// A. The shape's blocks move nothing as they are read. G70 then follows
// the shape at its own F and returns to A.
TEST(RuntimeLatheShapes, StockRemovalInTurningThenFinishing) {
  Machine m(kLathe);
  blocks(m, {"G97 S1000 G00 X60. Z2.", "G71 U2. R0.5",
             "G71 P10 Q20 U0.4 W0.1 F0.25", "N10 G00 X30.", "G01 Z-20. F0.1",
             "X50. Z-30."});
  EXPECT_EQ(m.motions().size(), 1U); // reading the shape
  const Points path = blocks(m, {"N20 Z-40."});
  Points expected{{60, 2}};
  const double stops[] = {-39.9, -39.9, -28.7, -26.7, -24.7, -22.7, -20.7};
  double level = 60.0;
  for (const double stop : stops) {
    level -= 4.0;
    expected.insert(expected.end(), {{level, 2},
                                     {level, stop},
                                     {level + 1.0, stop + 0.5},
                                     {level + 1.0, 2}});
  }
  expected.insert(
      expected.end(),
      {{30.4, 2.1}, {30.4, -19.9}, {50.4, -29.9}, {50.4, -39.9}, {60, 2}});
  expectPath(path, expected);
  EXPECT_EQ(m.motions()[2].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[2].feed, 0.25);
  EXPECT_EQ(m.motions()[2].cycle, 71);
  EXPECT_EQ(m.read(5001), 60.0);
  const std::size_t before = m.motions().size();
  blocks(m, {"G70 P10 Q20"});
  EXPECT_EQ(ends(m, before),
            (Points{{30, 2}, {30, -20}, {50, -30}, {50, -40}, {60, 2}}));
  EXPECT_EQ(m.motions()[before].kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions()[before + 1].feed, 0.1);
  EXPECT_EQ(m.motions()[before + 1].cycle, 70);
}

// G72 type I: the same with the axes exchanged: cuts 2 mm apart in Z (Z0,
// -2, -4) along X to the shape shifted by the allowance (0.2 of diameter,
// 0.1 in Z).
TEST(RuntimeLatheShapes, StockRemovalInFacing) {
  Machine m(kLathe);
  const Points path = blocks(m, {"G97 S1000 G00 X62. Z2.", "G72 W2. R0.5",
                                 "G72 P30 Q40 U0.2 W0.1 F0.2", "N30 G00 Z-6.",
                                 "G01 X40.", "N40 X20. Z-2."});
  const Points expected{{62, 2},    {62, 0},      {20.2, 0},    {21.2, 0.5},
                        {62, 0.5},  {62, -2},     {20.7, -2},   {21.7, -1.5},
                        {62, -1.5}, {62, -4},     {30.7, -4},   {31.7, -3.5},
                        {62, -3.5}, {62.2, -5.9}, {40.2, -5.9}, {20.2, -1.9},
                        {62, 2}};
  expectPath(path, expected);
}

// G73: three passes along the shape shifted by the allowance plus a relief
// of 3 (radius) and 1 (Z) shrinking to 0, each from A and back to it.
TEST(RuntimeLatheShapes, PatternRepeating) {
  Machine m(kLathe);
  const Points path =
      blocks(m, {"G97 S1000 G00 X60. Z5.", "G73 U3. W1. R3",
                 "G73 P50 Q60 U0.4 W0.1 F0.2", "N50 G00 X30. Z1.", "G01 Z-20.",
                 "N60 X50. Z-30."});
  const Points expected{{60, 5}, {36.4, 2.1}, {36.4, -18.9}, {56.4, -28.9},
                        {60, 5}, {33.4, 1.6}, {33.4, -19.4}, {53.4, -29.4},
                        {60, 5}, {30.4, 1.1}, {30.4, -19.9}, {50.4, -29.9},
                        {60, 5}};
  expectPath(path, expected);
}

TEST(RuntimeLatheShapes, Alarms) {
  Machine missing(kLathe);
  EXPECT_EQ(missing.block("G70 P10"), status(AlarmId::ShapeAddressMissing));
  Machine arc(kLathe);
  blocks(arc, {"G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0.4 W0.1 F0.2"});
  EXPECT_EQ(arc.block("N10 G02 X30. Z-2. R10."),
            status(AlarmId::ShapeFirstBlock));
  Machine back(kLathe);
  blocks(back, {"G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F0.2",
                "N10 G00 X30.", "G01 Z-10.", "X40."});
  EXPECT_EQ(back.block("N20 X35. Z-20."), status(AlarmId::ShapeNotMonotonic));
  // Type II (the control tells it by the words of block ns: Z written
  // counts even where it does not move, W0, and for G72 X) runs and says
  // that its moves between cuts are reconstructed (lathe_pockets.cpp).
  for (const char* first :
       {"N10 G00 X30. Z0", "N10 G00 X30. W0", "N10 G00 X30. Z2."}) {
    Machine written(kLathe);
    blocks(written,
           {"G98 G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F200.", first});
    EXPECT_EQ(written.block("N20 G01 Z-10."), 0) << first;
    EXPECT_NE(written.messages().find("G71 P10 Q20 type II"), std::string::npos)
        << first;
  }
  Machine facing(kLathe);
  blocks(facing, {"G98 G00 X62. Z2.", "G72 W2. R0.5", "G72 P30 Q40 F200.",
                  "N30 G00 X62. Z-6."});
  EXPECT_EQ(facing.block("N40 G01 X20."), 0);
  EXPECT_NE(facing.messages().find("G72 P30 Q40 type II"), std::string::npos);
  // A type II shape may dip across the cuts, not turn back along them.
  Machine turning(kLathe);
  blocks(turning, {"G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F0.2",
                   "N10 G00 X30. Z0", "G01 Z-10."});
  EXPECT_EQ(turning.block("N20 X40. Z-5."), status(AlarmId::ShapeNotMonotonic));
  EXPECT_TRUE(reports(turning, "turns back along the cuts"));
  Machine elsewhere(kLathe);
  blocks(elsewhere, {"G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F0.2"});
  EXPECT_EQ(elsewhere.block("N5 G00 X30."), status(AlarmId::Unsupported));
  Machine ending(kLathe);
  blocks(ending,
         {"G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F0.2", "N10 G00 X30."});
  EXPECT_EQ(ending.block("M30"), status(AlarmId::ShapeCommand));
}

// Tool nose radius compensation, an OD tool (tip 3) of R0.8 turning a 45
// degree chamfer X16-X20 and the diameter after it: the imaginary tip runs
// on the programmed X and Z of straight moves, and the chamfer's path moves
// R (1 - tan 22.5) = 0.4686 along Z (the handbook's compensation of a 45
// degree chamfer). With tip 0 the nose centre is the control point: the
// same path R (0.8 radius, 1.6 of diameter) above and R to the right.
// A run that ends while a shape cycle reads its shape program (the host
// stopped before nf) leaves nothing behind: the next run's moves are made,
// not read into a shape (RunControl::shapeCycle starts at 0).
TEST(RuntimeLatheShapes, ANewRunReadsNoShape) {
  Machine m(kLathe);
  blocks(m, {"G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0.4 W0.1 F0.2",
             "N10 G00 X30."});
  const size_t before = m.motions().size();
  mbrt_start(m.ctx(), "O1001");
  ASSERT_EQ(m.block("G00 X50. Z5."), 0);
  ASSERT_EQ(m.motions().size(), before + 1);
  EXPECT_EQ(m.motions().back().end[0], 50.0);
  EXPECT_EQ(m.motions().back().end[1], 5.0);
}

TEST(RuntimeLatheNoseRadius, ChamferWithTheTipDirection) {
  const char* profile = R"({"series": "T", "tool_offsets": {
      "1": {"r_geometry": 0.6, "r_wear": 0.2, "tip": 3}}})";
  Machine m(profile);
  const Points path =
      blocks(m, {"G98 T0101", "G00 X16. Z2.", "G42 G01 Z0 F100.", "X20. Z-2.",
                 "Z-10.", "G40 G00 X30."});
  const double shift = 0.8 * (1.0 - std::tan(std::numbers::pi / 8.0));
  // Positions are whole counts of 0.0005 mm.
  expectPath(path,
             {{16, 2}, {16, -shift}, {20, -2.0 - shift}, {20, -10}, {30, -10}},
             0.0003);
  Machine centre(R"({"series": "T", "tool_offsets": {
      "1": {"r_geometry": 0.8, "tip": 0}}})");
  const Points centred =
      blocks(centre, {"G98 T0101", "G00 X16. Z2.", "G42 G01 Z0 F100.",
                      "X20. Z-2.", "Z-10.", "G40 G00 X30."});
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_NEAR(centred[i].first, path[i].first + 1.6, 0.0011) << i;
    EXPECT_NEAR(centred[i].second, path[i].second + 0.8, 0.0011) << i;
  }
}

// Tool nose radius compensation in the cycles: an OD tool (tip 3) of R0.8.
// The path of the imaginary tip is the programmed path moved by the tip
// vector (-0.8 radius, -0.8 in Z) and offset 0.8 to the right of travel
// (G42; G90 and G94 choose the side of the cut themselves). Straight moves
// along Z or X keep the tip on their programmed line; where the start-up
// (-X) meets the first cut (-Z), both offset lines meet 0.8 + 0.8 below the
// approach: Z = 2 - 1.6 = 0.4.
constexpr const char* kNoseR08 =
    R"({"series": "T", "tool_offsets": {"1": {"r_geometry": 0.8, "tip": 3}}})";

// G90 X46 Z-30 from X52 Z2 with G41 in force (the cycle takes G42 for an
// OD cut towards the chuck): the start-up ends at (46, 0.4); the cut along
// Z and the shoulder meet on the programmed corner (46, -30) (the shoulder's
// offset line, 0.8 right of +X, moved back 0.8 by the tip: Z = -30); the
// shoulder ends where its line meets the return's (+Z, offset 0.8 below,
// moved 0.8 down by the tip: radius 26 - 1.6, X 48.8); the return to the
// start point cancels the vector. G92 and G75 run as without compensation.
TEST(RuntimeLatheNoseRadius, SingleAndGroovingCyclesUnderCompensation) {
  Machine m(kNoseR08);
  blocks(m, {"G98 T0101", "G00 X52. Z2.", "G41"});
  const std::size_t before = m.motions().size();
  blocks(m, {"G90 X46. Z-30. F100."});
  EXPECT_EQ(ends(m, before),
            (Points{{46, 0.4}, {46, -30}, {48.8, -30}, {52, 2}}));
  EXPECT_EQ(m.motions()[before].kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions()[before + 2].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[before].cycle, 90);
  EXPECT_EQ(m.read(5001), 52.0);
  // G94 X30 Z-2 from X52 Z2: facing towards the centre, the part beyond
  // in -Z, so G41. The start-up (-Z) and the face (-X) meet on the face's
  // programmed line: Z -2 (offset 0.8 left of -X is +Z, the tip -0.8).
  const std::size_t face = m.motions().size();
  blocks(m, {"G94 X30. Z-2."});
  EXPECT_EQ(ends(m, face).at(1).second, -2.0);
  EXPECT_EQ(ends(m, face).back(), (std::pair<double, double>{52, 2}));
  for (const char* cycle : {"G92 X48. Z-20. F1.5", "G75 R0.5"}) {
    Machine plain(kNoseR08);
    Machine under(kNoseR08);
    // The approach under G42 is held; the cycle ends it on its point.
    blocks(plain,
           {"G98 G97 S500 T0101", "G00 X60. Z-10.", "G01 X52. F100.", cycle});
    blocks(under, {"G98 G97 S500 T0101", "G00 X60. Z-10.", "G42 G01 X52. F100.",
                   cycle});
    const char* second = "G75 X40. Z-16. P2000 Q3000 F50.";
    if (std::string_view(cycle).starts_with("G75")) {
      blocks(plain, {second});
      blocks(under, {second});
    }
    EXPECT_EQ(ends(under), ends(plain)) << cycle;
  }
}

// G71 under G42: the cycle roughs the compensated shape. Shape: X30 (the
// start-up from A X60 Z2), Z-20, X50. Its tip path: (30, 0.4), (30, -20),
// and the last move ends on its perpendicular vector (+Z 0.8, the tip
// -0.8 in both): (48.4, -20). With the allowance (0.4 of diameter, 0.1)
// every cut stops at Z-19.9 and the last pass follows (30.4, 0.5),
// (30.4, -19.9), (48.8, -19.9). G70 runs the shape under compensation and
// its return to A cancels the vector: the last move (+X) meets the
// return's offset line (the return (22, 5) in Z and radius, offset 0.8 to
// its right and moved by the tip) at radius 23.4199 + 5 * 0.6227 / 22.
TEST(RuntimeLatheNoseRadius, ShapeCyclesUnderCompensation) {
  Machine m(kNoseR08);
  const Points path = blocks(m, {"G98 T0101", "G00 X60. Z2.", "G42",
                                 "G71 U2. R0.5", "G71 P10 Q20 U0.4 W0.1 F100.",
                                 "N10 G00 X30.", "G01 Z-20. F50.", "N20 X50."});
  Points expected{{60, 2}};
  for (double level = 56.0; level > 30.4; level -= 4.0) {
    expected.insert(
        expected.end(),
        {{level, 2}, {level, -19.9}, {level + 1.0, -19.4}, {level + 1.0, 2}});
  }
  expected.insert(expected.end(),
                  {{30.4, 0.5}, {30.4, -19.9}, {48.8, -19.9}, {60, 2}});
  expectPath(path, expected, 0.0003);
  const std::size_t before = m.motions().size();
  blocks(m, {"G70 P10 Q20"});
  const Points finish = ends(m, before);
  ASSERT_EQ(finish.size(), 4U);
  expectPath({finish[0], finish[1]}, {{30, 0.4}, {30, -20}});
  EXPECT_NEAR(finish[2].first, 2.0 * (23.4199 + 5.0 * 0.6227 / 22.0), 0.001);
  EXPECT_EQ(finish[2].second, -20.0);
  EXPECT_EQ(finish[3], (std::pair<double, double>{60, 2}));
  EXPECT_EQ(m.motions()[before + 1].feed, 50.0);
  // G41/G42 and G40 in the shape program: the same shape compensated from
  // N10 and cancelled by N20's move (ending on its programmed point).
  Machine inShape(kNoseR08);
  blocks(inShape, {"G98 T0101", "G00 X60. Z2.", "G70 P10 Q20",
                   "N10 G00 G42 X30.", "G01 Z-20. F50.", "N20 G40 X50."});
  expectPath(ends(inShape, 1), {{30, 0.4}, {30, -20}, {50, -20}, {60, 2}});
}

// Chamfering and corner R: from (X20 Z0), X30 K-1 stops 1 (radius) short
// of the corner at X28 and chamfers 45 degrees to Z-1; Z-20 R2 stops at
// Z-18 and turns clockwise (moving -Z, turning to +X) about (X34, Z-18)
// to (X34, Z-20); X40 goes on from there; Z-30 I1 chamfers to (X42, Z-30).
// U and W in the block after a corner count from the corner.
TEST(RuntimeLatheCorners, ChamfersAndCornerR) {
  Machine m(kLathe);
  const Points path = blocks(m, {"G98 G00 X20. Z0", "G01 X30. K-1. F100.",
                                 "W-20. R2.", "U10.", "Z-30. I1.", "X50."});
  expectPath(path, {{20, 0},
                    {28, 0},
                    {30, -1},
                    {30, -18},
                    {34, -20},
                    {40, -20},
                    {40, -29},
                    {42, -30},
                    {50, -30}});
  EXPECT_EQ(m.motions()[4].kind, MBRT_MOTION_CW);
  EXPECT_EQ(m.motions()[4].center[0], -18.0);          // Z
  EXPECT_EQ(m.motions()[4].center[1], 34.0);           // X, a diameter
  EXPECT_EQ(m.motions()[2].line, m.motions()[1].line); // the chamfer's block
  // With 3405#4 CCR, C gives the chamfer instead of I and K.
  Machine byC(R"({"series": "T", "parameters": {"3405": 16}})");
  expectPath(blocks(byC, {"G98 G00 X20. Z0", "G01 X30. C-1. F100.",
                          "Z-10. C-2.", "X20."}),
             {{20, 0}, {28, 0}, {30, -1}, {30, -8}, {26, -10}, {20, -10}});
}

TEST(RuntimeLatheCorners, Alarms) {
  const struct {
    const char* held;
    const char* next;
    AlarmId alarm;
  } cases[] = {
      {"Z-10. R2.", "G00 X40.", AlarmId::NotG01AfterCorner},
      {"Z-10. R2.", "G70 P10 Q20", AlarmId::NotG01AfterCorner},
      {"Z-10. R2.", "G04 U1.", AlarmId::NotG01AfterCorner},
      {"Z-10. R2.", "G28 U0", AlarmId::NotG01AfterCorner},
      {"Z-10. R2.", "G02 X34. Z-12. R2.", AlarmId::NotG01AfterCorner},
      {"Z-10. R2.", "X40. Z-12.", AlarmId::MissingMoveAfterCorner},
      {"Z-10. R2.", "X20.", AlarmId::MissingMoveAfterCorner},
      {"Z-10. R2.", "M08", AlarmId::MissingMoveAfterCorner},
      {"Z-10. R2.", "X32.", AlarmId::MissingCornerMove},
      {"Z-1. R2.", "X40.", AlarmId::MissingCornerMove},
      {"X34. Z-10. R2.", "X40.", AlarmId::TaperInCorner},
      {"Z-10. K2.", "X40.", AlarmId::TaperInCorner},
      {"Z-10. I2. R2.", "X40.", AlarmId::TooManyAddressCommands},
  };

  for (const auto& c : cases) {
    Machine m(kLathe);
    blocks(m, {"G98 G00 X30. Z0", "G01 F100."});
    const mbrt_status held = m.block(c.held);
    const mbrt_status next = held == 0 ? m.block(c.next) : held;
    EXPECT_EQ(next, status(c.alarm)) << c.held << " / " << c.next;
    EXPECT_EQ(m.motions().size(), 1U) << c.held << " / " << c.next;
  }
}

} // namespace
} // namespace mbc::test
