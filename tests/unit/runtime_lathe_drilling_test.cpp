// A lathe's drilling cycles G83-G85 (face, along Z) and G87-G89 (side,
// along X): R from the initial level, pecks by parameters 5101#2 and 5114,
// the return level by G code system. Points are (X, Z), X a diameter.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kLathe = R"({"series": "T"})";

// From Z5 (the initial level), R-2 is Z3. Q8000 is 8 mm: feed to Z-5, back
// 0.1 (5114) to Z-4.9, feed to Z-13, back to Z-12.9, feed to Z-20, rapid
// out to the initial level (system A has no G99 return).
TEST(RuntimeLatheDrilling, HighSpeedPeckOnCenter) {
  Machine m(kLathe);
  blocks(m, {"G98 G00 X0 Z5."});
  EXPECT_EQ(blocks(m, {"G83 Z-20. R-2. Q8000 F100."}), (Points{{0, 5},
                                                               {0, 3},
                                                               {0, -5},
                                                               {0, -4.9},
                                                               {0, -13},
                                                               {0, -12.9},
                                                               {0, -20},
                                                               {0, 5}}));
  EXPECT_EQ(m.motions()[1].kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions()[2].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[2].cycle, 83);
  EXPECT_EQ(m.read(4010), 83.0);
  blocks(m, {"G80"});
  EXPECT_EQ(m.read(4010), 80.0);
}

// 5101#2 RTR: out to R after each peck, in again to 0.1 short.
TEST(RuntimeLatheDrilling, PeckOutToR) {
  Machine m(R"({"series": "T", "parameters": {"5101": 4}})");
  blocks(m, {"G98 G00 X0 Z5."});
  EXPECT_EQ(
      blocks(m, {"G83 Z-12. R-2. Q8. F100."}),
      (Points{{0, 5}, {0, 3}, {0, -5}, {0, 3}, {0, -4.9}, {0, -12}, {0, 5}}));
}

// Without Q, one feed to the bottom; the next block drills again at its
// position (U adds 10 of diameter); W is the bottom measured from R.
TEST(RuntimeLatheDrilling, DrillTapAndBore) {
  Machine m(kLathe);
  blocks(m, {"G98 G00 X0 Z5."});
  EXPECT_EQ(blocks(m, {"G83 Z-10. R-2. F100.", "U10. W-8."}),
            (Points{{0, 5},
                    {0, 3},
                    {0, -10},
                    {0, 5},
                    {10, 5},
                    {10, 3},
                    {10, -5},
                    {10, 5}}));
  Machine tap(kLathe);
  blocks(tap, {"G98 G00 X0 Z5."});
  // Tapping and boring feed back out to R, then rapid to the initial level.
  EXPECT_EQ(blocks(tap, {"G84 Z-15. R-2. F150.", "G85 Z-10. R-1. P500"}),
            (Points{{0, 5},
                    {0, 3},
                    {0, -15},
                    {0, 3},
                    {0, 5},
                    {0, 4},
                    {0, -10},
                    {0, 4},
                    {0, 5}}));
  EXPECT_EQ(tap.motions()[3].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(tap.motions()[3].cycle, 84);
}

// G87 drills along X at Z and C: from X50 (radius 25) R-2 is radius 23
// (X46); each C moves to the next hole. A face cycle after it takes Z as
// its initial level.
TEST(RuntimeLatheDrilling, SideDrillingWithC) {
  Machine m(R"({"series": "T", "axes": ["X", "Z", "C"]})");
  blocks(m, {"G98 G00 X50. Z-10. C0"});
  EXPECT_EQ(blocks(m, {"G87 X20. R-2. F100.", "C90."}), (Points{{50, -10},
                                                                {46, -10},
                                                                {20, -10},
                                                                {50, -10},
                                                                {50, -10},
                                                                {46, -10},
                                                                {20, -10},
                                                                {50, -10}}));
  EXPECT_EQ(m.motions()[4].end[2], 90.0);
  const std::size_t before = m.motions().size();
  blocks(m, {"G83 X30. Z-20. R-1.", "G80"});
  EXPECT_EQ(ends(m, before),
            (Points{{30, -10}, {30, -11}, {30, -20}, {30, -10}}));
}

// G code system B: G99 returns to R, G98 to the initial level.
TEST(RuntimeLatheDrilling, ReturnLevelInSystemB) {
  Machine m(R"({"series": "T", "parameters": {"3401": 64}})");
  blocks(m, {"G94 G00 X0 Z5."});
  EXPECT_EQ(blocks(m, {"G99 G83 Z-20. R-2. F100.", "G98 Z-10."}),
            (Points{{0, 5}, {0, 3}, {0, -20}, {0, 3}, {0, -10}, {0, 5}}));
}

TEST(RuntimeLatheDrilling, Alarms) {
  Machine m(kLathe);
  blocks(m, {"G98 G00 X20. Z5."});
  EXPECT_EQ(m.block("G87 Z-10. R-1. F100."),
            status(AlarmId::ImproperNcAddress)); // no X, the bottom
  EXPECT_NE(m.report().find("without X"), std::string::npos);
  Machine noC(kLathe);
  EXPECT_EQ(noC.block("G83 C90. Z-5. F100."),
            status(AlarmId::ImproperNcAddress));
}

} // namespace
} // namespace mbc::test
