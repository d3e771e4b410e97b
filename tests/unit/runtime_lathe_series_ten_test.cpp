// A lathe's multiple repetitive cycles in the Series 10/11 tape format
// (parameter 0001#1 FCV): each is one block, the settings the standard
// format's first block gives are in it (D, I, K, A) or are parameters.
// Each cuts the passes the two-block cycle cuts from the same values,
// whose paths runtime_lathe_test.cpp derives by hand.
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

/// The same cycle in the two formats, from the same start point: the
/// standard format's blocks on a lathe with 5133/5139 = 0.5, the Series
/// 10/11 blocks with FCV and the same parameters.
void expectSameCycle(std::initializer_list<const char*> standardBlocks,
                     std::initializer_list<const char*> seriesTenBlocks) {
  Machine standard(R"({"series": "T", "parameters": {"5133": 0.5,
                       "5139": 0.5}})");
  Machine seriesTen(R"({"series": "T", "parameters": {"1": 2, "5133": 0.5,
                        "5139": 0.5}})");
  const Points expected = blocks(standard, standardBlocks);
  const Points path = blocks(seriesTen, seriesTenBlocks);
  EXPECT_GT(expected.size(), 8U);
  EXPECT_EQ(path, expected);
}

TEST(RuntimeLatheSeriesTen, OneBlockG71G72) {
  // G71 P Q U W D(Δd, increments) F: e is parameter 5133.
  expectSameCycle(
      {"G97 S1000 G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 U0.4 W0.1 F0.25",
       "N10 G00 X30.", "G01 Z-20. F0.1", "X50. Z-30.", "N20 Z-45."},
      {"G97 S1000 G00 X60. Z2.", "G71 P10 Q20 U0.4 W0.1 D2000 F0.25",
       "N10 G00 X30.", "G01 Z-20. F0.1", "X50. Z-30.", "N20 Z-45."});
  expectSameCycle({"G97 S1000 G00 X82. Z2.", "G72 W1.5 R0.5",
                   "G72 P10 Q20 U0.2 W0.1 F0.2", "N10 G00 Z-12.", "G01 X40.",
                   "Z-6.", "N20 X20. Z0."},
                  {"G97 S1000 G00 X82. Z2.", "G72 P10 Q20 U0.2 W0.1 D1500 F0.2",
                   "N10 G00 Z-12.", "G01 X40.", "Z-6.", "N20 X20. Z0."});
}

TEST(RuntimeLatheSeriesTen, OneBlockG71WithoutDTakesTheParameter) {
  // No D: the depth of cut is parameter 5132 (here 2 mm).
  Machine withD(R"({"series": "T", "parameters": {"1": 2}})");
  Machine withoutD(R"({"series": "T", "parameters": {"1": 2, "5132": 2}})");
  const Points expected =
      blocks(withD, {"G97 S900 G00 X60. Z2.", "G71 P10 Q20 D2000 F0.25",
                     "N10 G00 X30.", "N20 G01 Z-20."});
  EXPECT_EQ(blocks(withoutD, {"G97 S900 G00 X60. Z2.", "G71 P10 Q20 F0.25",
                              "N10 G00 X30.", "N20 G01 Z-20."}),
            expected);
}

TEST(RuntimeLatheSeriesTen, OneBlockG73) {
  // G73 P Q I(Δi) K(Δk) U W D(divisions) F.
  expectSameCycle(
      {"G97 S1000 G00 X60. Z5.", "G73 U3. W1. R3", "G73 P50 Q60 U0.4 W0.1 F0.2",
       "N50 G00 X30. Z1.", "G01 Z-20.", "N60 X50. Z-30."},
      {"G97 S1000 G00 X60. Z5.", "G73 P50 Q60 I3. K1. U0.4 W0.1 D3 F0.2",
       "N50 G00 X30. Z1.", "G01 Z-20.", "N60 X50. Z-30."});
}

TEST(RuntimeLatheSeriesTen, OneBlockG74G75) {
  // I is the amount along X, K along Z (least increments without a
  // decimal point), D the relief at the bottom; e is parameter 5139.
  expectSameCycle(
      {"G97 S600 G00 X20. Z2.", "G74 R0.5",
       "G74 X10. Z-12. P2500 Q4000 R0.2 F0.1"},
      {"G97 S600 G00 X20. Z2.", "G74 X10. Z-12. I2500 K4000 D200 F0.1"});
  expectSameCycle({"G97 S600 G00 X52. Z-20.", "G75 R0.5",
                   "G75 X40. Z-26. P2000 Q2500 F0.05"},
                  {"G97 S600 G00 X52. Z-20.", "G75 X40. Z-26. I2. K2.5 F0.05"});
}

TEST(RuntimeLatheSeriesTen, SingleCycleTaperIsIOrK) {
  // G90 and G92 give the taper as I, G94 as K, where the standard format
  // gives R.
  expectSameCycle({"G97 S600 G00 X52. Z2.", "G90 X40. Z-20. R-2. F0.2", "X36.",
                   "G00 X30. Z5.", "G92 X24. Z-15. R-1. F1.5", "G00 X60. Z2.",
                   "G94 X20. Z-2. R-1. F0.2", "Z-4."},
                  {"G97 S600 G00 X52. Z2.", "G90 X40. Z-20. I-2. F0.2", "X36.",
                   "G00 X30. Z5.", "G92 X24. Z-15. I-1. F1.5", "G00 X60. Z2.",
                   "G94 X20. Z-2. K-1. F0.2", "Z-4."});
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
  // G71-G75 are one block too; the message gives the format.
  const auto firstBlock = [](const char* text, AlarmId alarm,
                             const char* format) {
    Machine one(kSeriesTen);
    EXPECT_EQ(one.block(text), status(alarm)) << text;
    EXPECT_NE(one.report().find(format), std::string::npos) << one.report();
  };
  firstBlock("G71 U2. R0.5", AlarmId::ShapeAddressMissing, "P Q U W D F");
  firstBlock("G73 U3. W1. R3", AlarmId::ShapeAddressMissing, "P Q I K U W D F");
  firstBlock("G74 R0.5", AlarmId::IllegalRepetitiveCycle, "X(U) Z(W) I K D F");
  // D counts least increments: no decimal point.
  EXPECT_EQ(m.block("G71 P10 Q20 U0.4 W0.1 D2. F0.25"),
            status(AlarmId::IllegalDecimalPoint));
  EXPECT_EQ(m.block("G75 X20. Z-30. I1000 K2000 D.5 F0.1"),
            status(AlarmId::IllegalDecimalPoint));
  // Without FCV the one-block G76's A is no address; the message says why.
  Machine standard(R"({"series": "T"})");
  EXPECT_EQ(standard.block("G76 X17.5 Z-30. K1.2 D400 F2. A60"),
            status(AlarmId::ImproperNcAddress));
  EXPECT_NE(standard.report().find("0001#1 FCV"), std::string::npos);
}

} // namespace
} // namespace mbc::test
