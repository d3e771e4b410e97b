// The offset memory by the profile's names, in the machine's unit
// (runtime.h): what a state file saves and loads. Work offsets are kept in
// the machine's unit, so G20 and back loses nothing.
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
