// G71 type II against geometry of its own: a shape with a pocket between
// two rises, its finished outline sampled here as a function of Z, and the
// cycle's moves checked against it. The facts checked are those the
// sources agree on (docs/language.md): no move enters the finished shape;
// every cut level clears all the stock above the shape at that level; the
// pocket nearest the start is cut to its bottom before the next one; and
// the last pass runs along the shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kLathe = R"({"series": "T"})";

/// The finished outline, diameters: (z, x) corners from Z0 to Z-60.
const std::vector<std::pair<double, double>> kOutline = {
    {0.0, 30.0},   {-10.0, 30.0}, {-20.0, 50.0}, {-30.0, 50.0},
    {-35.0, 36.0}, {-45.0, 36.0}, {-50.0, 56.0}, {-60.0, 56.0}};

using Outline = std::vector<std::pair<double, double>>;

/// The outline's diameter at z (between its corners, by interpolation).
double outlineAt(const Outline& outline, double z) {
  for (std::size_t i = 0; i + 1 < outline.size(); ++i) {
    const auto [z0, x0] = outline[i];
    const auto [z1, x1] = outline[i + 1];
    if (z <= z0 && z >= z1) {
      return z0 == z1 ? std::min(x0, x1)
                      : x0 + (z - z0) * (x1 - x0) / (z1 - z0);
    }
  }
  return 0.0; // beyond the outline: nothing to cut into
}

struct Move {
  bool rapid;
  double x0, z0, x1, z1;
};

std::vector<Move> cycleMoves(const Machine& m) {
  std::vector<Move> moves;
  for (const mbrt_motion& motion : m.motions()) {
    if (motion.cycle == 0) {
      continue;
    }
    EXPECT_TRUE(motion.kind == MBRT_MOTION_RAPID ||
                motion.kind == MBRT_MOTION_LINEAR);
    moves.push_back({motion.kind == MBRT_MOTION_RAPID, motion.start[0],
                     motion.start[1], motion.end[0], motion.end[1]});
  }
  return moves;
}

/// No move goes into the finished shape, sampled along every move.
void expectOutside(const std::vector<Move>& moves, const Outline& outline) {
  const double first = outline.front().first;
  const double last = outline.back().first;
  for (const Move& move : moves) {
    for (int i = 0; i <= 100; ++i) {
      const double s = i / 100.0;
      const double x = move.x0 + s * (move.x1 - move.x0);
      const double z = move.z0 + s * (move.z1 - move.z0);
      if (z <= first && z >= last) {
        ASSERT_GE(x, outlineAt(outline, z) - 1e-6)
            << "into the shape at X" << x << " Z" << z;
      }
    }
  }
}

TEST(RuntimeLathePockets, CutsEachPocketToItsBottomWithoutEnteringTheShape) {
  Machine m(kLathe);
  blocks(m, {"G98 G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F100.",
             "N10 G00 X30. Z2.", "G01 Z-10.", "X50. Z-20.", "Z-30.",
             "X36. Z-35.", "Z-45.", "X56. Z-50.", "N20 Z-60."});
  const std::vector<Move> moves = cycleMoves(m);
  ASSERT_FALSE(moves.empty());
  expectOutside(moves, kOutline);
  // Every level, 4 mm of diameter apart from X60, is cut wherever the
  // shape lies below it.
  for (double level = 56.0; level > 30.0; level -= 4.0) {
    for (double z = -0.25; z > -60.0; z -= 0.5) {
      if (outlineAt(kOutline, z) >= level - 1e-6) {
        continue;
      }
      const bool cut =
          std::any_of(moves.begin(), moves.end(), [&](const Move& mv) {
            return !mv.rapid && mv.x0 == level && mv.x1 == level &&
                   z <= std::max(mv.z0, mv.z1) && z >= std::min(mv.z0, mv.z1);
          });
      EXPECT_TRUE(cut) << "X" << level << " Z" << z << " left";
    }
  }
  // Below X50 the start region and the pocket are apart: every cut of the
  // first comes before any cut of the pocket.
  const auto cutBelow50 = [](const Move& mv) {
    const double k = (60.0 - mv.x0) / 4.0; // a cut runs along a level
    return !mv.rapid && mv.x0 == mv.x1 && mv.x0 < 50.0 && k == std::floor(k);
  };
  const auto inPocket = [&](const Move& mv) {
    return cutBelow50(mv) && std::min(mv.z0, mv.z1) > -50.0 &&
           std::max(mv.z0, mv.z1) < -20.0;
  };
  const auto inStart = [&](const Move& mv) {
    return cutBelow50(mv) && std::max(mv.z0, mv.z1) > -20.0;
  };
  const auto firstPocket = std::find_if(moves.begin(), moves.end(), inPocket);
  const auto lastStart =
      std::find_if(moves.rbegin(), moves.rend(), inStart).base();
  ASSERT_NE(firstPocket, moves.end());
  EXPECT_LT(lastStart - moves.begin(), firstPocket - moves.begin());
  // The pocket is cut down to its bottom: its deepest cut is at X40, the
  // last level above X36.
  EXPECT_TRUE(std::any_of(moves.begin(), moves.end(), [&](const Move& mv) {
    return inPocket(mv) && mv.x0 == 40.0;
  }));
  // The last pass follows the shape from its start and returns to A.
  const auto pass =
      std::find_if(moves.rbegin(), moves.rend(), [](const Move& mv) {
        return mv.x1 == 30.0 && mv.z1 == 2.0;
      }).base();
  ASSERT_GE(moves.end() - pass, static_cast<long>(kOutline.size()));
  for (std::size_t i = 1; i < kOutline.size(); ++i) {
    const Move& along = pass[static_cast<long>(i) - 1];
    EXPECT_NEAR(along.z1, kOutline[i].first, 1e-9) << i;
    EXPECT_NEAR(along.x1, kOutline[i].second, 1e-9) << i;
  }
  const Move& back = moves.back();
  EXPECT_TRUE(back.rapid);
  EXPECT_EQ(back.x1, 60.0);
  EXPECT_EQ(back.z1, 2.0);
}

// A shape that ends low, in a pocket beyond a rise: the way back to A
// rises first, where a straight rapid would cross the rise.
TEST(RuntimeLathePockets, ReturnsToAWithoutCrossingARise) {
  Machine m(kLathe);
  blocks(m, {"G98 G00 X60. Z2.", "G71 U2. R0.5", "G71 P10 Q20 F100.",
             "N10 G00 X30. Z2.", "G01 Z-10.", "X50. Z-20.", "Z-30.",
             "N20 X30. Z-40."});
  expectOutside(cycleMoves(m), {{2.0, 30.0},
                                {-10.0, 30.0},
                                {-20.0, 50.0},
                                {-30.0, 50.0},
                                {-40.0, 30.0}});
}

} // namespace
} // namespace mbc::test
