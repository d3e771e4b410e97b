// A lathe's G76 in the Series 10/11 tape format (parameter 0001#1 FCV):
// one block, X Z I(taper) K(height) D(first depth) F A(angle) P(method),
// the rest from parameters. It cuts the passes the two-block G76 cuts
// from the same values.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kSeriesTen =
    R"({"series": "T", "parameters": {"1": 2, "5142": 2, "5130": 10,
        "5140": 0.1, "5141": 0.02, "5143": 60}})";

TEST(RuntimeLatheSeriesTen, OneBlockThreadIsTheTwoBlockThread) {
  Machine twoBlocks(R"({"series": "T"})");
  for (const char* text :
       {"G97 S600 M03", "G00 X26. Z5.", "G76 P021060 Q100 R0.02",
        "G76 X17.546 Z-30. R-0.5 P1227 Q400 F2."}) {
    ASSERT_EQ(twoBlocks.block(text), 0) << text << twoBlocks.report();
  }
  for (const char* threadBlock :
       {"G76 X17.546 Z-30. I-0.5 K1.227 D400 F2. A60 P1",
        "G76 X17.546 Z-30. I-0.5 K1227 D400 F2."}) { // K in increments, 5143
    Machine oneBlock(kSeriesTen);
    for (const char* text : {"G97 S600 M03", "G00 X26. Z5.", threadBlock}) {
      ASSERT_EQ(oneBlock.block(text), 0) << text << oneBlock.report();
    }
    EXPECT_GT(ends(oneBlock).size(), 20U);
    EXPECT_EQ(ends(oneBlock), ends(twoBlocks)) << threadBlock;
  }
}

TEST(RuntimeLatheSeriesTen, Alarms) {
  Machine m(kSeriesTen);
  ASSERT_EQ(m.block("G97 S600 M03 G00 X26. Z5."), 0);
  EXPECT_EQ(m.block("G76 X17.5 Z-30. K1.2 D400 F2. P2"),
            status(AlarmId::Unsupported)); // zigzag infeed
  EXPECT_EQ(m.block("G76 P021060 Q100 R0.02"),
            status(AlarmId::IllegalRepetitiveCycle)); // a first block
  EXPECT_EQ(m.block("G76 X17.5 Z-30. K1.2 F2."),
            status(AlarmId::IllegalRepetitiveCycle)); // no first depth D
  EXPECT_EQ(m.block("G71 P10 Q20 U0.4 W0.1 D2000 F0.25"),
            status(AlarmId::Unsupported));
  // Without FCV the one-block G76's A is no address; the message says why.
  Machine standard(R"({"series": "T"})");
  EXPECT_EQ(standard.block("G76 X17.5 Z-30. K1.2 D400 F2. A60"),
            status(AlarmId::ImproperNcAddress));
  EXPECT_NE(standard.report().find("0001#1 FCV"), std::string::npos);
}

} // namespace
} // namespace mbc::test
