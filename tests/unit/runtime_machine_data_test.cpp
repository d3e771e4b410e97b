// The offset memory by the profile's names, in the machine's unit
// (runtime.h): what a state file saves and loads. Work offsets are kept in
// the machine's unit, so G20 and back loses nothing.
#include <cmath>
#include <string>

#include "runtime_test_support.h"

namespace mbc::test {

TEST(RuntimeMachineData, WorkOffsetsSurviveTheOtherUnit) {
  Machine m;
  ASSERT_EQ(m.write(5221, -123.457), 0);
  blocks(m, {"G20", "G21", "G20", "G21"});
  EXPECT_EQ(m.read(5221), -123.457); // 0.0001 inch steps would lose it
  ASSERT_EQ(m.block("G20"), 0);
  EXPECT_EQ(m.read(5221), -4.8605); // shown in the unit in force
  double value = 0.0;
  ASSERT_EQ(mbrt_get_work_offset(m.ctx(), "G54", 0, &value), 1);
  EXPECT_EQ(value, -123.457); // kept in the machine's
  // A G20 write is stored in millimetres, to the nearest 0.001.
  ASSERT_EQ(m.write(5222, 1.0), 0);
  ASSERT_EQ(mbrt_get_work_offset(m.ctx(), "G54", 1, &value), 1);
  EXPECT_EQ(value, 25.4);
  EXPECT_EQ(m.read(5222), 1.0);
}

TEST(RuntimeMachineData, NamesOfTheProfile) {
  Machine m(R"({"axes": ["X", "Y", "Z", "B"]})");
  EXPECT_STREQ(mbrt_work_offset_set(0), "EXT");
  EXPECT_STREQ(mbrt_work_offset_set(1), "G54");
  EXPECT_STREQ(mbrt_work_offset_set(7), "G54.1P1");
  EXPECT_STREQ(mbrt_work_offset_set(306), "G54.1P300");
  EXPECT_EQ(mbrt_work_offset_set(307), nullptr);
  ASSERT_EQ(mbrt_set_work_offset(m.ctx(), "G54.1P12", 3, 90.5), 1);
  EXPECT_EQ(m.read(14001 + 11 * 20 + 3), 90.5); // degrees on B
  EXPECT_EQ(mbrt_set_work_offset(m.ctx(), "G60", 0, 1.0), 0);
  EXPECT_EQ(mbrt_set_work_offset(m.ctx(), "G54", 4, 1.0), 0);
  EXPECT_EQ(mbrt_set_work_offset(m.ctx(), "G54", 0, 1e9), 0);
  std::string fields;
  for (int i = 0; const char* field = mbrt_tool_offset_field(m.ctx(), i); ++i) {
    fields += std::string(field) + ' ';
  }
  EXPECT_EQ(fields, "h_geometry h_wear d_geometry d_wear ");
  ASSERT_EQ(mbrt_set_tool_offset(m.ctx(), 3, "d_geometry", 4.0004), 1);
  EXPECT_EQ(m.read(13003), 4.0); // to the increment
  EXPECT_EQ(mbrt_set_tool_offset(m.ctx(), 3, "x_wear", 1.0), 0);
}

TEST(RuntimeMachineData, ALathesOffsets) {
  Machine m(R"({"series": "T", "tool_offsets": {"count": 8}})");
  ASSERT_EQ(mbrt_set_tool_offset(m.ctx(), 3, "x_geometry", -10.25), 1);
  ASSERT_EQ(mbrt_set_tool_offset(m.ctx(), 3, "tip", 3), 1);
  EXPECT_EQ(mbrt_set_tool_offset(m.ctx(), 3, "tip", 10), 0);
  EXPECT_EQ(mbrt_set_tool_offset(m.ctx(), 9, "x_wear", 1.0), 0);
  EXPECT_EQ(mbrt_set_tool_offset(m.ctx(), 3, "h_geometry", 1.0), 0);
  EXPECT_EQ(m.read(15003), -10.25);
  EXPECT_EQ(m.read(13003), 3.0);
  double value = 0.0;
  ASSERT_EQ(mbrt_get_tool_offset(m.ctx(), 3, "x_geometry", &value), 1);
  EXPECT_EQ(value, -10.25);
  Machine wearOnly(R"({"series": "T", "tool_offsets": {
    "geometry_wear": false}})");
  EXPECT_EQ(mbrt_get_tool_offset(wearOnly.ctx(), 1, "x_geometry", &value), 0);
}

} // namespace mbc::test

namespace mbc::test {

// A host puts the tool where its own model left it: the next run starts
// there, and the work coordinates follow the offsets in force.
TEST(RuntimeMachineData, TheMachinePositionBetweenRuns) {
  Machine m;
  ASSERT_EQ(m.write(5221, -100.0), 0); // G54 X
  ASSERT_EQ(mbrt_set_machine_position(m.ctx(), 0, -60.0), 1);
  ASSERT_EQ(mbrt_set_machine_position(m.ctx(), 2, -12.3456), 1);
  double value = 0.0;
  ASSERT_EQ(mbrt_get_machine_position(m.ctx(), 2, &value), 1);
  EXPECT_EQ(value, -12.346); // to the least increment
  EXPECT_EQ(m.read(5021), -60.0);
  EXPECT_EQ(m.read(5041), 40.0); // in G54
  ASSERT_EQ(m.block("G91 G01 X5. F100."), 0);
  EXPECT_EQ(m.read(5021), -55.0);
  EXPECT_EQ(mbrt_set_machine_position(m.ctx(), 3, 1.0), 0); // no 4th axis
  EXPECT_EQ(mbrt_set_machine_position(m.ctx(), 0, 1e12), 0);
  EXPECT_EQ(mbrt_set_machine_position(m.ctx(), 0, std::nan("")), 0);
  EXPECT_EQ(mbrt_get_machine_position(m.ctx(), -1, &value), 0);
  // In inches a profile's position is in inches; a lathe's X a diameter.
  Machine inch(R"({"units": "inch"})");
  ASSERT_EQ(mbrt_set_machine_position(inch.ctx(), 0, 1.5), 1);
  EXPECT_EQ(inch.read(5021), 1.5);
  Machine lathe(R"({"series": "T"})");
  ASSERT_EQ(mbrt_set_machine_position(lathe.ctx(), 0, 80.0), 1);
  EXPECT_EQ(lathe.read(5021), 80.0);
  ASSERT_EQ(lathe.block("G00 U-20."), 0);
  ASSERT_EQ(mbrt_get_machine_position(lathe.ctx(), 0, &value), 1);
  EXPECT_EQ(value, 60.0);
}

} // namespace mbc::test
