// G10 programmable data input (runtime/src/machine/data_input.cpp).
#include "runtime_test_support.h"

namespace mbc::test {

TEST(RuntimeDataInput, WorkOffsetsSetAndAdd) {
  Machine m;
  ASSERT_EQ(m.block("G10 L2 P1 X-100. Z-200"), 0); // Z in increments
  EXPECT_EQ(m.read(5221), -100.0);
  EXPECT_EQ(m.read(5223), -0.2);
  ASSERT_EQ(m.block("G91 G10 L2 P1 X-0.5"), 0);
  EXPECT_EQ(m.read(5221), -100.5);
  ASSERT_EQ(m.block("G90 G10 L2 P0 Y3."), 0);
  EXPECT_EQ(m.read(5202), 3.0);
  ASSERT_EQ(m.block("G10 L20 P300 X7."), 0);
  EXPECT_EQ(m.read(14000 + 299 * 20 + 1), 7.0);
  // The machine stays where it is: the program position follows G54.
  EXPECT_EQ(m.read(5001), 100.5);
  EXPECT_TRUE(m.motions().empty());
}

TEST(RuntimeDataInput, ToolOffsetsByL) {
  Machine m;
  ASSERT_EQ(m.block("G10 L10 P1 R100."), 0);
  ASSERT_EQ(m.block("G10 L11 P1 R-0.25"), 0);
  ASSERT_EQ(m.block("G10 L12 P2 R5."), 0);
  ASSERT_EQ(m.block("G91 G10 L13 P2 R0.01"), 0);
  ASSERT_EQ(m.block("G10 L13 P2 R0.01"), 0);
  EXPECT_EQ(m.read(11001), 100.0);
  EXPECT_EQ(m.read(10001), -0.25);
  EXPECT_EQ(m.read(13002), 5.0);
  EXPECT_EQ(m.read(12002), 0.02);
}

TEST(RuntimeDataInput, Alarms) {
  Machine m;
  EXPECT_EQ(m.block("G10 L2 P7 X0", 3), status(AlarmId::IllegalPInG10));
  EXPECT_EQ(m.report(), "test.nc:3: alarm PS0031: ILLEGAL P COMMAND IN G10: "
                        "G10 L2 P7: P must be 0 to 6\n");
  Machine tool;
  EXPECT_EQ(tool.block("G10 L10 P401 R1."), status(AlarmId::IllegalPInG10));
  Machine toolLife; // tool life data: not modelled
  EXPECT_EQ(toolLife.block("G10 L3"), status(AlarmId::Unsupported));
  Machine bare;
  EXPECT_EQ(bare.block("G10 P1 R1."), status(AlarmId::Unsupported));
}

} // namespace mbc::test
