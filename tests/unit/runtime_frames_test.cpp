// Coordinate frames (runtime/src/moves/frames.cpp, machine/frame_codes.cpp):
// the words of G51, G68 and G43 under their parameters, what each frame does to
// arcs and units, and the alarms.
#include "runtime_test_support.h"

namespace mbc::test {

namespace {

double endOf(const Machine& m, int axis) {
  return m.motions().back().end[axis];
}

double machineOf(const Machine& m, int axis) {
  return m.motions().back().machine[axis];
}

/// #4008, #4011, #4016, #4018: tool length, scaling, rotation, mirror.
std::vector<double> frameGroups(Machine& m) {
  return {m.read(4008), m.read(4011), m.read(4016), m.read(4018)};
}

} // namespace

TEST(RuntimeFrames, ScalingMagnificationUnits) {
  Machine m;
  ASSERT_EQ(m.block("G51 X0 Y0 P150000"), 0); // 0.00001 units: 1.5
  ASSERT_EQ(m.block("G01 X10. F100"), 0);
  EXPECT_EQ(endOf(m, 0), 15.0);
  Machine scr(R"({"parameters": {"5400": 128}})"); // SCR: 0.001 units
  ASSERT_EQ(scr.block("G51 X0 Y0 P500"), 0);
  ASSERT_EQ(scr.block("G01 X10. F100"), 0);
  EXPECT_EQ(endOf(scr, 0), 5.0);
  Machine fallback(R"({"parameters": {"5411": 200000}})");
  ASSERT_EQ(fallback.block("G51 X10. Y0"), 0); // centre X10: 10 + 2 * (20 - 10)
  ASSERT_EQ(fallback.block("G01 X20. F100"), 0);
  EXPECT_EQ(endOf(fallback, 0), 30.0);
}

TEST(RuntimeFrames, PerAxisScalingMirrorsWithANegativeFactor) {
  Machine m(R"({"parameters": {"5400": 64}})"); // XSC: I J K per axis
  ASSERT_EQ(m.block("G51 X0 Y0 I-1. J2."), 0);
  ASSERT_EQ(m.block("G01 X10. Y10. F100"), 0);
  EXPECT_EQ(endOf(m, 0), -10.0);
  EXPECT_EQ(endOf(m, 1), 20.0);
  // An arc under unequal factors would be an ellipse.
  EXPECT_EQ(m.block("G02 X20. Y0 R10."), status(AlarmId::Unsupported));
}

TEST(RuntimeFrames, IllegalScaleRate) {
  Machine m;
  EXPECT_EQ(m.block("G51 X0 P0", 4), status(AlarmId::IllegalScaleRate));
  EXPECT_EQ(m.report(), "test.nc:4: alarm PS0142: ILLEGAL SCALE RATE: G51 "
                        "magnification 0\n");
  Machine negative;
  EXPECT_EQ(negative.block("G51 X0 P-2."), status(AlarmId::IllegalScaleRate));
}

TEST(RuntimeFrames, RotationAngleUnitsAndIncrementalAngle) {
  Machine m;
  ASSERT_EQ(m.block("G68 X0 Y0 R90000"), 0); // 0.001 degree: 90 degrees
  ASSERT_EQ(m.block("G01 X10. F100"), 0);
  EXPECT_EQ(endOf(m, 0), 0.0);
  EXPECT_EQ(endOf(m, 1), 10.0);
  Machine rin(R"({"parameters": {"5400": 1}})"); // RIN: R follows G91
  ASSERT_EQ(rin.block("G68 X0 Y0 R45."), 0);
  ASSERT_EQ(rin.block("G91 G68 R45."), 0);
  ASSERT_EQ(rin.block("G90 G01 X10. F100"), 0);
  EXPECT_EQ(endOf(rin, 0), 0.0);
  EXPECT_EQ(endOf(rin, 1), 10.0);
  Machine absolute; // without RIN a G91 R is the angle itself
  ASSERT_EQ(absolute.block("G68 X0 Y0 R45."), 0);
  ASSERT_EQ(absolute.block("G91 G68 R90."), 0);
  ASSERT_EQ(absolute.block("G90 G01 X10. F100"), 0);
  EXPECT_EQ(endOf(absolute, 1), 10.0);
}

TEST(RuntimeFrames, RotatedMovesDoNotDrift) {
  Machine m;
  ASSERT_EQ(m.block("G68 X0 Y0 R30."), 0);
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(m.block("G91 G01 X0.001 F100"), 0);
  }
  EXPECT_EQ(m.read(5001), 1.0);
  EXPECT_EQ(endOf(m, 0), 0.866); // cos 30 deg, rounded once
  EXPECT_EQ(endOf(m, 1), 0.5);
}

// A block moves only the axes it commands. The tool stood at X47.001
// Y50.003 when the frame came; the program position found from it is
// rounded, and mapping it forward again moved X or Y an increment with
// every Z move.
TEST(RuntimeFrames, AxesABlockLeavesAloneStay) {
  for (const char* frame : {"G68 X0 Y0 R30.", "G51 X0 Y0 P3.",
                            "G51 X0 Y0 I-3. J0.7", "G51.1 X10.0005"}) {
    Machine m;
    blocks(m, {"G90 G00 X47.001 Y50.003 Z0", frame, "G91 G01 Z-1. F100",
               "G81 Z-5. R1.", "G80 G90 G00 Z5.", "G91 G00 Z0"});
    ASSERT_GT(m.motions().size(), 4U) << frame;
    for (const mbrt_motion& move : m.motions()) {
      EXPECT_EQ(move.end[0], 47.001) << frame << " line " << move.line;
      EXPECT_EQ(move.end[1], 50.003) << frame << " line " << move.line;
    }
  }
}

TEST(RuntimeFrames, ArcInAnotherPlaneThanTheRotation) {
  Machine m;
  ASSERT_EQ(m.block("G68 X0 Y0 R45."), 0);
  EXPECT_EQ(m.block("G18 G02 X10. Z0 R5. F100"), status(AlarmId::Unsupported));
}

TEST(RuntimeFrames, OneFrameCodePerBlock) {
  Machine m;
  EXPECT_EQ(m.block("G52 X1. G92 X0", 2), status(AlarmId::ImproperGCode));
  EXPECT_EQ(m.report(),
            "test.nc:2: alarm PS0010: IMPROPER G-CODE: G52 and G92 in one "
            "block\n");
  Machine rotated;
  ASSERT_EQ(rotated.block("G68 X0 Y0 R10."), 0);
  EXPECT_EQ(rotated.block("G92 X0"), status(AlarmId::Unsupported));
}

TEST(RuntimeFrames, UnitSwitchKeepsTheLocalOriginAndTheOffset) {
  Machine m(R"({"tool_offsets": {"1": {"h_geometry": 25.4}}})");
  ASSERT_EQ(m.block("G21 G52 X25.4"), 0);
  ASSERT_EQ(m.block("G43 H1 G00 X0 Z0"), 0);
  EXPECT_EQ(machineOf(m, 0), 25.4);
  EXPECT_EQ(machineOf(m, 2), 25.4);
  ASSERT_EQ(m.block("G20 G00 X1."), 0);
  EXPECT_EQ(endOf(m, 0), 2.0); // local origin 1 inch + 1 inch
  EXPECT_EQ(machineOf(m, 2), 1.0);
  EXPECT_EQ(m.read(5083), 1.0);
}

TEST(RuntimeFrames, UnitSwitchKeepsTheG29IntermediatePoint) {
  Machine m;
  ASSERT_EQ(m.block("G21 G91 G28 X25.4"), 0);
  ASSERT_EQ(m.block("G20 G90 G29 X2."), 0);
  ASSERT_GE(m.motions().size(), 2u);
  // Through X 1 inch (the 25.4 mm of G28), then to X 2 inch.
  const auto& through = m.motions()[m.motions().size() - 2];
  EXPECT_EQ(through.machine[0], 1.0);
  EXPECT_EQ(endOf(m, 0), 2.0);
}

TEST(RuntimeFrames, ToolLengthTypeBFollowsThePlane) {
  Machine m(R"({"parameters": {"5001": 2},
                "tool_offsets": {"1": {"h_geometry": 10}}})");
  ASSERT_EQ(m.block("G19 G43 H1 G00 X0"), 0);
  EXPECT_EQ(machineOf(m, 0), 10.0); // YZ plane: the offset is on X
  EXPECT_EQ(m.read(5081), 10.0);
  EXPECT_EQ(m.read(5083), 0.0);
  Machine typeC(R"({"parameters": {"5001": 1}})");
  EXPECT_EQ(typeC.block("G43 H1 Z0"), status(AlarmId::Unsupported));
}

TEST(RuntimeFrames, ModalGroupsOfTheFrames) {
  Machine m;
  const std::vector<double> cancelled{49.0, 50.0, 69.0, 50.1};
  EXPECT_EQ(frameGroups(m), cancelled);
  ASSERT_EQ(m.block("G44 H0 G51 X0 P2."), 0);
  ASSERT_EQ(m.block("G68 R1."), 0);
  ASSERT_EQ(m.block("G51.1 Y0"), 0);
  EXPECT_EQ(frameGroups(m), (std::vector<double>{44.0, 51.0, 68.0, 51.1}));
  ASSERT_EQ(m.block("G49 G50 G69"), 0);
  ASSERT_EQ(m.block("G50.1"), 0);
  EXPECT_EQ(frameGroups(m), cancelled);
  EXPECT_TRUE(m.motions().empty());
}

} // namespace mbc::test
