// Cutter compensation C (runtime/src/moves/cutter_comp.cpp): what the
// block-by-block interface shows of the look-ahead, the alarms and the
// refusals. Every expected point is worked out by hand; the corner rules
// themselves are checked by the goldens and the oracle scripts.
#include "runtime/src/moves/plane_geometry.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "runtime_test_support.h"

namespace mbc::test {

using rt::PlaneCurve;
using rt::PlanePoint;

TEST(RuntimeCutterComp, TheMoveWaitsForTheNextOne) {
  Machine m;
  ASSERT_EQ(m.block("G10 L12 P1 R5."), 0);
  ASSERT_EQ(m.block("G90 G01 X-10. Y0 F500."), 0);
  ASSERT_EQ(m.block("G41 D1 X0"), 0); // straight on: no corner yet
  EXPECT_EQ(m.read(4007), 41.0);
  const std::size_t before = m.motions().size();
  ASSERT_EQ(m.block("X20."), 0);
  // The start-up leaves now, perpendicular to the next move (type A).
  ASSERT_EQ(m.motions().size(), before + 1);
  EXPECT_EQ(m.motions().back().end[0], 0.0);
  EXPECT_EQ(m.motions().back().end[1], 5.0);
  EXPECT_EQ(m.read(5001), 20.0); // the programmed point
  // Reading the tool position stops the look-ahead: X20. leaves on its
  // perpendicular vector.
  EXPECT_EQ(m.read(5042), 5.0);
  EXPECT_EQ(m.read(5041), 20.0);
  ASSERT_EQ(m.motions().size(), before + 2);
}

// FANUC: G41/G42 given again in offset mode makes the vector at the end
// of the move before perpendicular to it, instead of the intersection.
TEST(RuntimeCutterComp, G41AgainEndsTheMoveBeforePerpendicular) {
  for (const char* again : {"G41 Y20.", "G41"}) {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R5."), 0);
    ASSERT_EQ(m.block("G90 G01 X-10. Y0 F500."), 0);
    ASSERT_EQ(m.block("G41 D1 X0"), 0);
    ASSERT_EQ(m.block("X20."), 0); // held: an inner corner follows
    ASSERT_EQ(m.block(again), 0);
    ASSERT_FALSE(m.motions().empty());
    EXPECT_EQ(m.motions().back().end[0], 20.0) << again; // not 15
    EXPECT_EQ(m.motions().back().end[1], 5.0) << again;
  }
}

// G39 at an outer corner: the move before ends on its perpendicular vector
// (X20 Y5), then an arc of the offset about the corner turns the vector
// perpendicular to the direction given, Y up: from (20, 5) to (25, 0). At
// an inner corner (Y down, on the left of the path) the arc would turn 270
// degrees through the far side: refused.
TEST(RuntimeCutterComp, G39AtOuterCornersOnly) {
  Machine outer;
  blocks(outer, {"G10 L12 P1 R5.", "G90 G01 X-10. Y0 F500.", "G41 D1 X0",
                 "X20.", "G39 Y-10.", "Y-10."});
  const Points path = ends(outer, 2);
  ASSERT_GE(path.size(), 2U);
  EXPECT_EQ(path[0], std::make_pair(20.0, 5.0));
  EXPECT_EQ(path[1], std::make_pair(25.0, 0.0));
  EXPECT_EQ(outer.motions()[3].kind, MBRT_MOTION_CW);
  Machine inner;
  blocks(inner,
         {"G10 L12 P1 R5.", "G90 G01 X-10. Y0 F500.", "G41 D1 X0", "X20."});
  EXPECT_EQ(inner.block("G39 Y10.", 5), status(AlarmId::Unsupported));
}

// G40 X Y I J: the held move ends where its offset path meets the offset
// of a virtual path along I J from its end, inner corner or outer.
TEST(RuntimeCutterComp, G40WithIJMeetsTheVirtualPath) {
  const struct {
    const char* cancel;
    double x;
  } cases[] = {{"G40 X40. Y-10. I0 J1.", 25.0},  // inner: x = 30 - 5
               {"G40 X40. Y-10. I0 J-1.", 35.0}, // outer: x = 30 + 5
               {"G40 X40. Y-10. I1. J0", 30.0}}; // parallel: perpendicular

  for (const auto& c : cases) {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R5."), 0);
    ASSERT_EQ(m.block("G90 G01 X-10. Y0 F500."), 0);
    ASSERT_EQ(m.block("G41 D1 X0"), 0);
    ASSERT_EQ(m.block("X30."), 0);
    ASSERT_EQ(m.block(c.cancel), 0) << c.cancel;
    const auto& moves = m.motions();
    ASSERT_GE(moves.size(), 2U);
    EXPECT_EQ(moves[moves.size() - 2].end[0], c.x) << c.cancel;
    EXPECT_EQ(moves[moves.size() - 2].end[1], 5.0) << c.cancel;
    EXPECT_EQ(moves.back().end[0], 40.0);
    EXPECT_EQ(moves.back().end[1], -10.0);
    EXPECT_EQ(m.read(4007), 40.0);
  }
}

// G41 X Y I J at the start-up: the start-up ends where the offset of a
// virtual path along I J into its end meets the next move's offset path.
TEST(RuntimeCutterComp, G41WithIJStartsAlongTheVirtualPath) {
  const struct {
    const char* startUp;
    const char* next;
    double x;
    double y;
  } cases[] = {{"G41 D1 X0 Y0", "Y20.", -5.0, 2.071}, // inner: intersection
               {"G41 D1 X0 Y0 I1. J0", "Y20.", -5.0, 5.0}, // along +X: y = 5
               {"G41 D1 X0 Y0", "X20.", 0.0, 5.0},         // outer, type A
               {"G41 D1 X0 Y0 I0 J1.", "X20.", -5.0, 5.0}, // along +Y: x = -5
               {"G41 D1 X0 Y0 I1. J0", "X20.", 0.0, 5.0}}; // parallel: type A

  for (const auto& c : cases) {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R5."), 0);
    ASSERT_EQ(m.block("G90 G01 X-10. Y-10. F500."), 0);
    ASSERT_EQ(m.block(c.startUp), 0);
    ASSERT_EQ(m.block(c.next), 0) << c.startUp;
    EXPECT_EQ(m.motions().back().end[0], c.x) << c.startUp << " " << c.next;
    EXPECT_EQ(m.motions().back().end[1], c.y) << c.startUp << " " << c.next;
  }
  Machine m; // in offset mode the I J form is not modelled
  ASSERT_EQ(m.block("G10 L12 P1 R5."), 0);
  ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
  EXPECT_EQ(m.block("G41 X20. I1. J0"), status(AlarmId::Unsupported));
}

TEST(RuntimeCutterComp, NegativeOffsetSwapsTheSides) {
  Machine m;
  ASSERT_EQ(m.block("G10 L12 P2 R-3."), 0);
  ASSERT_EQ(m.block("G90 G41 D2 G01 X10. F300."), 0);
  ASSERT_EQ(m.read(5042), -3.0); // G41 with -3: right of the path
}

TEST(RuntimeCutterComp, D0CancelsLikeG40) {
  Machine m;
  ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
  ASSERT_EQ(m.block("G90 G41 D1 G01 X10. F300."), 0);
  ASSERT_EQ(m.block("D0 X20."), 0); // type A cancel: perpendicular, then on
  EXPECT_EQ(m.read(5041), 20.0);
  EXPECT_EQ(m.read(5042), 0.0);
  ASSERT_GE(m.motions().size(), 2U);
  EXPECT_EQ(m.motions()[m.motions().size() - 2].end[1], 4.0);
}

TEST(RuntimeCutterComp, AlarmsOfTheControl) {
  {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
    ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
    EXPECT_EQ(m.block("G31 X20."), status(AlarmId::SkipInCrc));
  }
  {
    Machine m;
    ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
    EXPECT_EQ(m.block("G19"), status(AlarmId::PlaneChangeInCrc));
  }
  {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
    ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
    EXPECT_EQ(m.block("G40 G02 X20. R5."),
              status(AlarmId::NoCircleAtStartOrCancel));
  }

  // Inside arcs of the offset's radius and smaller: PS0038, PS0041.
  const struct {
    const char* arc;
    AlarmId alarm;
  } insideArcs[] = {{"G03 X30. Y4. R4.", AlarmId::InterferenceInCircle},
                    {"G03 X30. Y3. R3.", AlarmId::InterferenceInCrc}};

  for (const auto& inside : insideArcs) {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
    ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
    ASSERT_EQ(m.block("X26."), 0);
    EXPECT_EQ(m.block(inside.arc), status(inside.alarm)) << inside.arc;
  }
  {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
    EXPECT_EQ(m.block("G39 X10."), status(AlarmId::ImproperGCode));
    EXPECT_EQ(m.block("D1 G01 X1. F100."), 0);
    EXPECT_EQ(m.block("G41 X10. D1000"), status(AlarmId::IllegalOffsetNumber));
  }
}

TEST(RuntimeCutterComp, WhatIsNotModelledStopsTheRun) {
  for (const char* block :
       {"G53 X0", "G81 X5. Z-1. R1.", "G52 X5.", "G92 X0", "G68 X0 Y0 R30.",
        "G55", "G20", "G10 L2 P1 X5.", "G41 I1. J0 X30."}) {
    Machine m;
    ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
    ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
    EXPECT_EQ(m.block(block), status(AlarmId::Unsupported)) << block;
  }
  Machine m; // a work offset written by a macro
  ASSERT_EQ(m.block("G42 D1 G01 X10. F300."), 0);
  EXPECT_EQ(m.write(5221, 1.0), status(AlarmId::Unsupported));
}

/// G41 with a 5 mm offset from X0 Y0 Z0 along X20., then Y20. held.
void startSquare(Machine& m) {
  ASSERT_EQ(m.block("G10 L12 P1 R5."), 0);
  ASSERT_EQ(m.block("G90 G01 X0 Y0 Z0 F500."), 0);
  ASSERT_EQ(m.block("G41 D1 X20."), 0);
  ASSERT_EQ(m.block("Y20."), 0);
}

// 0i-MB manual: G53 (and a return of Z alone) ends the move before on its
// perpendicular vector; with the plane's axes the vector goes, without
// them it stays.
TEST(RuntimeCutterComp, MachinePositioningEndsTheMoveBeforePerpendicular) {
  Machine m;
  startSquare(m);
  ASSERT_EQ(m.block("G91 G28 Z0"), 0);
  // Y20. left on its perpendicular vector, then Z to the reference.
  EXPECT_EQ(m.read(5041), 15.0);
  EXPECT_EQ(m.read(5042), 20.0);
  EXPECT_EQ(m.read(5001), 20.0); // the programmed point
  EXPECT_EQ(m.read(4007), 41.0);
  ASSERT_EQ(m.block("G90 G53 X0 Y0"), 0);
  EXPECT_EQ(m.read(5041), 0.0);
  EXPECT_EQ(m.read(5042), 0.0);
  // The next move in the plane is a start-up again (type A).
  ASSERT_EQ(m.block("G01 X10."), 0);
  ASSERT_EQ(m.block("Y10."), 0);
  EXPECT_EQ(m.read(5041), 5.0);
  EXPECT_EQ(m.read(5042), 10.0);
}

// 16/18-MC manual: a tool length offset change under compensation counts
// as a change of the offset value, from its own block on: the held move
// keeps the length it was read with.
TEST(RuntimeCutterComp, ToolLengthChangeActsFromItsBlock) {
  Machine m;
  ASSERT_EQ(m.block("G10 L10 P2 R10."), 0);
  startSquare(m);
  const std::size_t before = m.motions().size();
  ASSERT_EQ(m.block("G43 H2 Z-5."), 0); // held behind Y20.
  ASSERT_EQ(m.motions().size(), before);
  ASSERT_EQ(m.block("X0"), 0);
  // Y20. to the inner corner at its old length, then Z at the new one.
  ASSERT_EQ(m.motions().size(), before + 2);
  const mbrt_motion& corner = m.motions()[before];
  EXPECT_EQ(corner.end[0], 15.0);
  EXPECT_EQ(corner.end[1], 15.0);
  EXPECT_EQ(corner.machine[2], 0.0);
  EXPECT_EQ(m.motions().back().end[2], -5.0);
  EXPECT_EQ(m.motions().back().machine[2], 5.0);
  EXPECT_EQ(m.motions().back().end[1], 15.0);
  // G49 alone: a move of Z alone, the tool staying on its vector.
  ASSERT_EQ(m.block("G49"), 0);
  ASSERT_EQ(m.block("Y0"), 0);
  EXPECT_EQ(m.read(5043), -5.0);
  EXPECT_EQ(m.read(5041), 5.0);
  // Along an axis of the plane (G18: Z and X) it is not modelled.
  Machine side;
  ASSERT_EQ(side.block("G10 L12 P1 R5."), 0);
  ASSERT_EQ(side.block("G10 L10 P2 R10."), 0);
  ASSERT_EQ(side.block("G18 G90 G01 X0 Z0 F500."), 0);
  ASSERT_EQ(side.block("G41 D1 X20."), 0);
  EXPECT_EQ(side.block("G43 H2"), status(AlarmId::Unsupported));
}

TEST(RuntimeCutterComp, ParametersItDoesNotModelStopTheRun) {
  for (const char* parameters :
       {R"({"parameters": {"5003": 2}})", R"({"parameters": {"19607": 4}})"}) {
    Machine m(parameters);
    ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
    EXPECT_EQ(m.block("G41 D1 G01 X10. F300."), status(AlarmId::Unsupported))
        << parameters;
  }
  // 5003#2 CCN: the FS15 vector after G28, G29, G30 and G53.
  Machine m(R"({"parameters": {"5003": 4}})");
  ASSERT_EQ(m.block("G10 L12 P1 R4."), 0);
  ASSERT_EQ(m.block("G41 D1 G01 X10. F300."), 0);
  ASSERT_EQ(m.block("Y10."), 0);
  EXPECT_EQ(m.block("G53 X0 Y0"), status(AlarmId::Unsupported));
}

TEST(PlaneGeometry, LinesAndCirclesMeet) {
  PlaneCurve horizontal;
  horizontal.point = {0.0, 5.0};
  horizontal.direction = {1.0, 0.0};
  PlaneCurve vertical;
  vertical.point = {3.0, 0.0};
  vertical.direction = {0.0, 1.0};
  const auto corner = rt::intersections(horizontal, vertical);
  ASSERT_EQ(corner.size(), 1U);
  EXPECT_DOUBLE_EQ(corner[0].x, 3.0);
  EXPECT_DOUBLE_EQ(corner[0].y, 5.0);
  EXPECT_TRUE(rt::intersections(horizontal, horizontal).empty());

  PlaneCurve circle;
  circle.circle = true;
  circle.center = {0.0, 0.0};
  circle.radius = 13.0;
  const auto chord = rt::intersections(horizontal, circle);
  ASSERT_EQ(chord.size(), 2U); // 5-12-13
  EXPECT_DOUBLE_EQ(chord[0].x, -12.0);
  EXPECT_DOUBLE_EQ(chord[1].x, 12.0);
  circle.radius = 4.0;
  EXPECT_TRUE(rt::intersections(horizontal, circle).empty());
  // Points are in counts: a tangent join that rounding makes miss by a
  // fraction of a count touches at the foot of the perpendicular.
  circle.radius = 4.8;
  const auto touch = rt::intersections(horizontal, circle);
  ASSERT_EQ(touch.size(), 1U);
  EXPECT_DOUBLE_EQ(touch[0].x, 0.0);
  EXPECT_DOUBLE_EQ(touch[0].y, 5.0);

  circle.radius = 4.0;
  PlaneCurve other = circle;
  other.center = {6.0, 0.0};
  other.radius = 5.0; // circles of 4 and 5, 6 apart
  const auto both = rt::intersections(circle, other);
  ASSERT_EQ(both.size(), 2U);
  EXPECT_NEAR(both[0].x, 9.0 / 4.0, 1e-12); // (36 + 16 - 25) / 12
  EXPECT_NEAR(both[0].y, -both[1].y, 1e-12);
}

TEST(PlaneGeometry, WithinTurnIsFmodToTheBit) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  std::vector<double> angles;
  for (int k = 0; k <= 4; ++k) { // at and beside every whole turn
    const double at = k * kTurn;
    angles.insert(angles.end(), {at, std::nextafter(at, 0.0),
                                 std::nextafter(at, 10.0 * kTurn)});
  }
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> any(0.0, 4.0 * kTurn);
  for (int i = 0; i < 100000; ++i) {
    angles.push_back(any(random));
  }
  for (const double angle : angles) {
    if (angle >= 4.0 * kTurn) {
      continue;
    }
    const double expected = std::fmod(angle, kTurn);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(rt::withinTurn(angle)),
              std::bit_cast<std::uint64_t>(expected))
        << angle;
  }
}

} // namespace mbc::test
