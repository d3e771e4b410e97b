// A move held for look-ahead (a chamfer or corner R waiting for the next
// block, a move cutter or nose radius compensation holds) runs in the state
// of its own block: frames, offsets, compensation side and D, feed. The
// next block's G codes, offsets and tool act from the next block's own move.
// Every expected point is worked out by hand or from the corner's geometry
// with plain vector arithmetic here, never from mbc's output.
#include <cmath>
#include <string>

#include "runtime_test_support.h"

namespace mbc::test {

namespace {

constexpr const char* kMill = R"({"tool_offsets": {"count": 10,
  "1": {"d_geometry": 5, "h_geometry": 100}, "2": {"d_geometry": 2},
  "3": {"d_geometry": 1}}, "work_offsets": {"G55": [100, 0, 0]}})";

struct Vec {
  double x, y;
};

Vec operator+(Vec a, Vec b) {
  return {a.x + b.x, a.y + b.y};
}

Vec operator-(Vec a, Vec b) {
  return {a.x - b.x, a.y - b.y};
}

Vec operator*(double k, Vec a) {
  return {k * a.x, k * a.y};
}

Vec unitOf(Vec a) {
  const double n = std::hypot(a.x, a.y);
  return {a.x / n, a.y / n};
}

Vec leftNormal(Vec a) {
  return {-a.y, a.x};
}

/// Where the lines a0-a1 and b0-b1, each moved `offset` to its left, meet.
Vec offsetCorner(Vec a0, Vec a1, Vec b0, Vec b1, double offset) {
  const Vec da = unitOf(a1 - a0);
  const Vec db = unitOf(b1 - b0);
  const Vec pa = a0 + offset * leftNormal(da);
  const Vec pb = b0 + offset * leftNormal(db);
  const double det = da.x * db.y - da.y * db.x;
  const double t = ((pb.x - pa.x) * db.y - (pb.y - pa.y) * db.x) / det;
  return pa + t * da;
}

/// The moves a block at `line` made.
std::vector<mbrt_motion> movesOfLine(const Machine& m, int line) {
  std::vector<mbrt_motion> moves;
  for (const mbrt_motion& move : m.motions()) {
    if (move.line == line) {
      moves.push_back(move);
    }
  }
  return moves;
}

} // namespace

// The issue's program: a ,C corner on the last block before G40 ran its
// move as the cancel move, on the programmed contour (a 5 mm gouge).
TEST(RuntimeHeldMoves, ChamferBeforeG40KeepsTheOffset) {
  for (const char* profile :
       {kMill, R"({"tool_offsets": {"count": 10, "1": {"d_geometry": 5}},
                   "parameters": {"5003": 1}})"}) {
    Machine m(profile);
    blocks(m, {"G90 G00 X-10. Y-10. Z-5.", "G41 D1 G01 X0 Y0 F500.",
               "G01 Y40. ,C4.", "G01 X40. ,C4.", "G01 Y0 ,C4.", "G01 X0 ,C4.",
               "G40 G01 X-10. Y-10."});
    mbrt_finish(m.ctx(), MBRT_END_M02_M30);
    // Line 6 runs along X at Y-5 into its chamfer, an inner corner: the
    // tool centre ends where that line meets the chamfer's offset line.
    const std::vector<mbrt_motion> moves = movesOfLine(m, 6);
    ASSERT_EQ(moves.size(), 2U);
    const Vec leave{4.0, 0.0};
    const Vec join = 4.0 * unitOf({-10.0, -10.0});
    const Vec corner =
        offsetCorner({40.0, 0.0}, leave, leave, {-2.828, -2.828}, 5.0);
    EXPECT_EQ(moves[0].end[1], -5.0);
    EXPECT_NEAR(moves[0].end[0], corner.x, 0.001);
    // The chamfer's tool centre runs 5 mm left of the programmed chamfer.
    const Vec along = unitOf(join - leave);
    const Vec end{moves[1].end[0], moves[1].end[1]};
    const Vec fromLeave = end - leave;
    EXPECT_NEAR(along.x * fromLeave.y - along.y * fromLeave.x, 5.0, 0.001);
    EXPECT_EQ(m.motions().back().end[0], -10.0);
    EXPECT_EQ(m.motions().back().end[1], -10.0);
  }
}

// The next block changes the work coordinate system under a held corner:
// the corner's two moves would lie in two systems.
TEST(RuntimeHeldMoves, NewWorkSystemUnderAHeldCornerStops) {
  Machine m(kMill);
  blocks(m, {"G90 G54 G00 X0 Y0 Z0", "G01 X20. ,C2. F100."});
  EXPECT_EQ(m.block("G55 Y20.", 3), status(AlarmId::Unsupported));
  EXPECT_NE(m.report().find("a work coordinate system change between a "
                            "chamfer, corner R or ,A line (line 2)"),
            std::string::npos)
      << m.report();
  for (const mbrt_motion& move : m.motions()) {
    EXPECT_LE(move.machine[0], 20.0); // never the G55 X120 of the bug
  }
}

TEST(RuntimeHeldMoves, WorkOffsetWriteUnderAHeldCornerStops) {
  Machine m(kMill);
  blocks(m, {"G90 G54 G00 X0 Y0 Z0", "G01 X20. ,R2. F100."});
  EXPECT_EQ(m.write(5221, 5.0), status(AlarmId::Unsupported));
  EXPECT_EQ(m.write(5241, 5.0), 0); // G55's: not the system in force
}

// G43 H in the next block: the X move and its corner R keep the length
// offset of their block; the next block's Y move takes the new one.
TEST(RuntimeHeldMoves, LengthOffsetActsFromItsOwnBlock) {
  Machine m(kMill);
  blocks(m, {"G90 G00 X0 Y0 Z0", "G01 X20. ,R2. F100.", "G43 H1 Y20."});
  const std::vector<mbrt_motion> held = movesOfLine(m, 2);
  ASSERT_EQ(held.size(), 2U); // to the arc, the arc
  for (const mbrt_motion& move : held) {
    EXPECT_EQ(move.machine[2], 0.0);
  }
  EXPECT_EQ(held[0].end[0], 18.0);
  EXPECT_EQ(held[1].end[0], 20.0);
  EXPECT_EQ(held[1].end[1], 2.0);
  const std::vector<mbrt_motion> next = movesOfLine(m, 3);
  ASSERT_EQ(next.size(), 1U);
  EXPECT_EQ(next[0].end[1], 20.0);
  EXPECT_EQ(next[0].machine[2], 100.0);
}

// The feed and feed mode of the held block: a G95 in the next block acts
// from its own move.
TEST(RuntimeHeldMoves, HeldCornerKeepsItsFeed) {
  Machine m(kMill);
  blocks(m, {"G90 G94 G00 X0 Y0 Z0 S1000", "G01 X20. ,C2. F100.",
             "G95 Y20. F0.5"});
  for (const mbrt_motion& move : movesOfLine(m, 2)) {
    EXPECT_EQ(move.feed, 100.0);
  }
  // 18 + 2.828 mm at 100 mm/min, then 18 mm at 0.5 mm/rev and 1000 rpm.
  const double seconds = (18.0 + 2.0 * std::sqrt(2.0)) / 100.0 * 60.0 +
                         18.0 / (0.5 * 1000.0) * 60.0;
  EXPECT_NEAR(m.read(3001), seconds * 1000.0, 1.0);
}

namespace {

/// Under G41 D2 from (-10, 0): X20. ,C3. then `next`, a block to X30 Y40.
/// Returns the end of the X20 block's move along X.
Vec xPieceEnd(const char* next, int* status, Machine& m) {
  blocks(m, {"G90 G00 X-10. Y0 Z0", "G41 D2 G01 X0 Y0 F100.", "X20. ,C3."});
  *status = m.block(next, 4);
  const std::vector<mbrt_motion> moves = movesOfLine(m, 3);
  return moves.empty() ? Vec{NAN, NAN} : Vec{moves[0].end[0], moves[0].end[1]};
}

} // namespace

// What the next block changes in compensation (side, D, G41 again, D0,
// G40) acts from its own move: the X20 block and its chamfer run on the
// left at D2 = 2 whatever follows.
TEST(RuntimeHeldMoves, CompensationChangesActFromTheNextMove) {
  const Vec leave{17.0, 0.0};
  const Vec join = Vec{20.0, 0.0} + 3.0 * unitOf({10.0, 40.0});
  // An inner corner on the left: the X line and the chamfer, both at 2.
  const Vec corner = offsetCorner({0.0, 0.0}, leave, leave, join, 2.0);
  for (const char* next : {"G42 X30. Y40.", "D3 X30. Y40.", "G41 X30. Y40.",
                           "D0 X30. Y40.", "G40 X30. Y40."}) {
    Machine m(kMill);
    int status = -1;
    const Vec end = xPieceEnd(next, &status, m);
    EXPECT_EQ(status, 0) << next;
    EXPECT_EQ(end.y, 2.0) << next;
    EXPECT_NEAR(end.x, corner.x, 0.001) << next;
    // The chamfer's tool centre runs 2 mm left of the programmed chamfer.
    // To the chamfer, the chamfer, and for G42 the link to the right side.
    const std::vector<mbrt_motion> moves = movesOfLine(m, 3);
    ASSERT_EQ(moves.size(), next[1] == '4' && next[2] == '2' ? 3U : 2U) << next;
    const Vec along = unitOf(join - leave);
    const Vec at = Vec{moves[1].end[0], moves[1].end[1]} - leave;
    const double beside = along.x * at.y - along.y * at.x;
    // The chamfer ends on its offset line, or perpendicular to it (G41
    // again, a side change), always 2 mm to its left.
    EXPECT_NEAR(beside, 2.0, 0.001) << next;
  }
}

// A block whose move a chamfer holds is a move in the plane, not a block
// without motion: after a Z move (the one 19625 allows) the X20 move still
// meets the next one at the inner corner's intersection, not on its
// perpendicular vector (an overcut).
TEST(RuntimeHeldMoves, AHeldCornerIsNoBlockWithoutMotion) {
  Machine m(kMill);
  blocks(m, {"G90 G00 X-10. Y0 Z0", "G41 D2 G01 X0 Y0 F100.", "X20.", "Z-1.",
             "Y20. ,C2.", "X0"});
  const std::vector<mbrt_motion> moves = movesOfLine(m, 3);
  ASSERT_EQ(moves.size(), 1U);
  EXPECT_EQ(moves[0].end[0], 18.0);
  EXPECT_EQ(moves[0].end[1], 2.0);
}

// ,R in G40, then G41 D2 in the next block: the block without G41 runs as
// programmed; the next move is the start-up.
TEST(RuntimeHeldMoves, StartUpActsFromItsOwnBlock) {
  Machine m(kMill);
  blocks(m, {"G90 G00 X0 Y0 Z0", "G01 X20. ,R5. F100.", "G41 D2 Y20.", "X0"});
  const std::vector<mbrt_motion> held = movesOfLine(m, 2);
  ASSERT_EQ(held.size(), 2U);
  EXPECT_EQ(held[0].end[0], 15.0);
  EXPECT_EQ(held[0].end[1], 0.0);
  EXPECT_EQ(held[1].end[0], 20.0);
  EXPECT_EQ(held[1].end[1], 5.0);
  // The start-up (type A) ends perpendicular to its move's end: X18.
  const std::vector<mbrt_motion> startUp = movesOfLine(m, 3);
  ASSERT_FALSE(startUp.empty());
  EXPECT_EQ(startUp.front().end[0], 18.0);
}

namespace {

// Tool 2 and tool 3 share their geometry (0) and differ in wear; tool 4
// has a geometry offset of its own.
constexpr const char* kLathe = R"({"series": "T", "tool_offsets": {
  "2": {"x_wear": 0.2, "z_wear": -0.1, "r_geometry": 0.4, "tip": 3},
  "3": {"x_wear": -0.4, "z_wear": 0.3, "r_geometry": 0.8, "tip": 3},
  "4": {"x_geometry": -10, "z_geometry": 5}}})";

/// The offset a move ran with: machine less workpiece position, X a
/// diameter.
Vec offsetOf(const mbrt_motion& move) {
  return {move.machine[0] - move.end[0], move.machine[1] - move.end[1]};
}

} // namespace

// A lathe's chamfer (K) held while the next block selects another wear
// offset: the chamfer block runs with T02's, the next move with T03's.
TEST(RuntimeHeldMoves, LatheChamferKeepsItsToolsWear) {
  Machine m(kLathe);
  blocks(m, {"G00 X50. Z5. T0202", "G01 X30. K-2. F0.2 S500", "T0303 Z-20."});
  const std::vector<mbrt_motion> held = movesOfLine(m, 2);
  ASSERT_EQ(held.size(), 2U); // to X34 (d), the chamfer to Z3 (c)
  for (const mbrt_motion& move : held) {
    EXPECT_NEAR(offsetOf(move).x, 0.2, 1e-9);
    EXPECT_NEAR(offsetOf(move).y, -0.1, 1e-9);
  }
  EXPECT_EQ(held[0].end[0], 34.0);
  EXPECT_EQ(held[1].end[0], 30.0);
  EXPECT_EQ(held[1].end[1], 3.0);
  const std::vector<mbrt_motion> next = movesOfLine(m, 3);
  ASSERT_EQ(next.size(), 1U);
  EXPECT_NEAR(offsetOf(next[0]).x, -0.4, 1e-9);
  EXPECT_NEAR(offsetOf(next[0]).y, 0.3, 1e-9);
}

// Another geometry offset is a new coordinate system: under a held corner
// or an offset vector it stops the run rather than bend the corner.
TEST(RuntimeHeldMoves, LatheGeometryChangeUnderAHeldMoveStops) {
  for (const char* held : {"G01 X30. K-2. F0.2", "G42 G01 X30. F0.2"}) {
    Machine m(kLathe);
    blocks(m, {"G00 X50. Z5. T0202 S500", held});
    EXPECT_EQ(m.block("T0404 Z-20.", 3), status(AlarmId::Unsupported)) << held;
  }
}

// Nose radius compensation holds X30. while T0303 is read: the held move
// leaves with T02's wear, the Z move with T03's.
TEST(RuntimeHeldMoves, LatheCompensatedMoveKeepsItsToolsWear) {
  Machine m(kLathe);
  blocks(m, {"G00 X50. Z5. T0202", "G42 G01 X30. Z0 F0.2 S500", "X40.",
             "T0303 Z-20.", "G40 G00 X60."});
  const std::vector<mbrt_motion> held = movesOfLine(m, 3);
  ASSERT_FALSE(held.empty());
  for (const mbrt_motion& move : held) {
    EXPECT_NEAR(offsetOf(move).x, 0.2, 1e-9);
    EXPECT_NEAR(offsetOf(move).y, -0.1, 1e-9);
  }
  const std::vector<mbrt_motion> next = movesOfLine(m, 4);
  ASSERT_FALSE(next.empty());
  for (const mbrt_motion& move : next) {
    EXPECT_NEAR(offsetOf(move).x, -0.4, 1e-9);
    EXPECT_NEAR(offsetOf(move).y, 0.3, 1e-9);
  }
}

} // namespace mbc::test
