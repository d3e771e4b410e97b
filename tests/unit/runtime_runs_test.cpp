// One run after another in a context: what a new run keeps of the machine
// (as a control after RESET) and what the reset calls put back.
#include "runtime/src/core/context.h"

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

constexpr const char* kClearOnReset = R"({"parameters": {"3402": 64}})";

/// A first run that leaves the tool at X10 in G91 G01 with F, S and M set,
/// then the start of the second.
void runThenStartAnother(Machine& m) {
  ASSERT_EQ(m.block("G91 G01 X10. F250 S1200 M03"), 0);
  mbrt_start(m.ctx(), "O1001");
}

void expectVariables(Machine& m,
                     std::initializer_list<std::pair<int, double>> expected) {
  for (const auto& [number, value] : expected) {
    EXPECT_EQ(m.read(number), value) << '#' << number;
  }
}

// The reset state: modal codes and the last words (#4101+) stay.
TEST(RuntimeRuns, ARunGoesOnFromWhereTheLastLeftTheTool) {
  Machine m;
  runThenStartAnother(m);
  expectVariables(
      m, {{4003, 91}, {4001, 1}, {4109, 250}, {4119, 1200}, {4113, 3}});
  ASSERT_EQ(m.block("X5."), 0);
  ASSERT_EQ(m.motions().size(), 2U);
  EXPECT_EQ(m.motions()[1].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(m.motions()[1].start[0], 10.0);
  EXPECT_EQ(m.motions()[1].end[0], 15.0);
  EXPECT_STREQ(m.motions()[1].program, "O1001");
}

// 3402#6 CLR, the clear state: power-on codes, no last words; the tool
// stays where it is.
TEST(RuntimeRuns, ClearStateTakesThePowerOnCodesButNotThePosition) {
  Machine m(kClearOnReset);
  runThenStartAnother(m);
  expectVariables(
      m, {{4003, 90}, {4001, 0}, {4109, 0}, {4119, 0}, {4113, 0}, {5001, 10}});
  ASSERT_EQ(m.block("X4."), 0);
  EXPECT_EQ(m.motions().back().kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions().back().start[0], 10.0);
  EXPECT_EQ(m.motions().back().end[0], 4.0);
}

TEST(RuntimeRuns, ANewRunCancelsWhatResetCancels) {
  Machine m;
  ASSERT_EQ(m.block("G90 G00 Z10."), 0);
  ASSERT_EQ(m.block("G81 X1. Y1. Z-2. R1. F100"), 0);
  ASSERT_EQ(m.write(3004, 7), 0);
  const size_t holeMoves = m.motions().size();
  mbrt_start(m.ctx(), "O1000");
  EXPECT_EQ(m.read(4009), 80.0);
  EXPECT_EQ(m.read(3004), 0.0);
  ASSERT_EQ(m.block("X5."), 0); // a rapid, not another hole
  ASSERT_EQ(m.motions().size(), holeMoves + 1);
  EXPECT_EQ(m.motions().back().kind, MBRT_MOTION_RAPID);
  EXPECT_EQ(m.motions().back().cycle, 0);
}

// The machine's state as a whole returns to power-on at mbrt_reset_state,
// whatever a program left in it: no field of it can outlive the reset.
// #3002 is machine data and stays.
TEST(RuntimeRuns, ResetStateLeavesNoMachineStateBehind) {
  Machine m(R"({"tool_offsets": {"1": {"h_geometry": 50}}})");
  for (const char* block :
       {"G20", "G92 X1. Y2. Z3.", "G52 X3.", "G68 X0 Y0 R30.", "G51 X0 Y0 P2.",
        "G43 H1 Z1.", "G91 G28 Z0", "G90 G31 X5. F100", "G16",
        "G99 G83 X1. Y1. Z-1. R1. Q0.5 F50", "G95 G64 G18", "M29 S500"}) {
    ASSERT_EQ(m.block(block), 0) << block << "\n" << m.report();
  }
  ASSERT_EQ(m.write(3002, 5.0), 0);
  mbrt_reset_state(m.ctx());
  // A mill's power-on state is the state's defaults.
  rt::MachineState expected;
  expected.clockHours = 5.0;
  EXPECT_TRUE(m.ctx()->machine == expected);
  EXPECT_EQ(m.read(3002), 5.0);
}

TEST(RuntimeRuns, ResetStateHomesTheMachineAndKeepsItsData) {
  Machine m;
  ASSERT_EQ(m.write(500, 7), 0);
  ASSERT_EQ(m.block("G91 G01 X10. Y3. F100"), 0);
  ASSERT_EQ(m.block("G92 X0 Y0"), 0);
  mbrt_reset_state(m.ctx());
  EXPECT_EQ(m.read(4003), 90.0);
  EXPECT_EQ(m.read(5021), 0.0);
  EXPECT_EQ(m.read(5001), 0.0);
  EXPECT_EQ(m.read(500), 7.0);
  ASSERT_EQ(m.block("X4."), 0);
  EXPECT_EQ(m.motions().back().start[0], 0.0);
  EXPECT_EQ(m.motions().back().end[0], 4.0);
  mbrt_reset(m.ctx());
  EXPECT_TRUE(isVacant(m.read(500)));
}

// docs/embedding.md lists what carries over from one run to the next in a
// context without a reset; each item is read here after a new start.
TEST(RuntimeRuns, WhatTheNextRunKeeps) {
  Machine m(R"({"tool_offsets": {"1": {"h_geometry": 50}}})");
  blocks(m, {"G10 L2 P1 X5.", "G10 L12 P1 R4.", "G52 X1.", "G43 H1",
             "G91 G01 X10. F600.", "G66 P9000", "G81 Z-1. R1."});
  for (const auto& [number, value] : {std::pair{100, 1.0},
                                      {500, 2.0},
                                      {3002, 3.0},
                                      {3003, 1.0},
                                      {3004, 7.0},
                                      {3005, 1.0},
                                      {1100, 1.0},
                                      {3902, 9.0}}) {
    ASSERT_EQ(m.write(number, value), 0) << '#' << number;
  }
  mbrt_finish(m.ctx(), MBRT_END_M02_M30);
  const double clock = m.read(3001);
  mbrt_start(m.ctx(), "O1000");
  expectVariables(m, {{5001, 4.0},  // position: machine 10 less G54 5 and G52 1
                      {5003, 0.0},  // back at the cycle's initial level
                      {4003, 91.0}, // modal codes
                      {4109, 600.0},  // last words
                      {5081 + 2, 50}, // the tool length offset in force
                      {100, 1.0},
                      {500, 2.0},
                      {5221, 5.0},
                      {13001, 4.0},
                      {3002, 3.0},
                      {3005, 1.0},
                      {1100, 1.0},
                      {3901, 1.0}, // M30 counted the part
                      {3902, 9.0},
                      {3001, clock},
                      // and what a new run cancels or clears
                      {4012, 67.0},
                      {4009, 80.0},
                      {4007, 40.0},
                      {3003, 0.0},
                      {3004, 0.0}});
}

/// Every variable a program can read, as (status, value) by number: what
/// one context shows of its state.
std::vector<std::pair<mbrt_status, double>> everyVariable(Machine& m) {
  std::vector<std::pair<mbrt_status, double>> values;
  for (int number = 1; number < 100000; ++number) {
    mbrt_num value = 0.0;
    const mbrt_status status = mbrt_read_var(m.ctx(), number, &value);
    values.emplace_back(status, isVacant(value) ? -1e300 : value);
  }
  return values;
}

/// A run that changes what it can of the machine and leaves moves held.
void changeEverything(Machine& m, bool lathe) {
  static const std::vector<const char*> kLathe = {"G10 P3 X0.2 Z-0.1 R0.4 Q3",
                                                  "G10 L2 P1 X1. Z-300.",
                                                  "G50 S2000",
                                                  "G96 S150 T0303",
                                                  "G01 X40. Z-5. F0.3",
                                                  "G71 U2. R0.5",
                                                  "G20",
                                                  "G21",
                                                  "G42 G01 X30. Z-10.",
                                                  "G01 X20. K-1."};
  static const std::vector<const char*> kMill = {
      "G10 L2 P2 X5. Y-3.",
      "G10 L12 P1 R5.",
      "G10 L10 P1 R100.",
      "G55 G43 H1 G00 X10. Y20. Z30.",
      "G52 X1.",
      "G92 X0 Y0",
      "G68 X0 Y0 R30.",
      "G91 G01 X5. F500.",
      "G20",
      "G21",
      "M98 P2",
      "G66 P9000 X1.",
      "G67",
      "G69 G50.1 X0",
      "G41 D1 G90 X20.",
      "Y20. ,C2."};
  for (const char* text : lathe ? kLathe : kMill) {
    EXPECT_EQ(m.block(text), 0) << text << m.report();
  }
  for (const auto& [number, value] : {std::pair{100, 1.0},
                                      {500, 2.0},
                                      {3002, 3.0},
                                      {3004, 7.0},
                                      {3005, 1.0},
                                      {1100, 1.0},
                                      {1133, 5.0},
                                      {3901, 4.0},
                                      {3902, 9.0}}) {
    EXPECT_EQ(m.write(number, value), 0) << '#' << number;
  }
  mbrt_finish(m.ctx(), MBRT_END_M02_M30);
}

// After mbrt_reset a context is as mbrt_create made it, whatever the runs
// before it changed (#3002, settings, signals, offsets, frames, held
// moves...): every variable reads the same as on a new context, and the
// same blocks make the same moves. Batches reset before each row.
TEST(RuntimeRuns, ResetGivesANewContext) {
  setenv("SOURCE_DATE_EPOCH", "1700000000", 1); // #3011/#3012
  for (const char* profile : {R"({"tool_offsets": {"1": {"h_geometry": 50}}})",
                              R"({"series": "T"})"}) {
    const bool lathe = profile[2] == 's';
    Machine fresh(profile);
    Machine used(profile);
    changeEverything(used, lathe);
    mbrt_reset(used.ctx());
    mbrt_start(used.ctx(), "O1000");
    EXPECT_EQ(everyVariable(used), everyVariable(fresh)) << profile;
    for (Machine* m : {&fresh, &used}) {
      mbrt_start(m->ctx(), "O1000"); // past the alarms of the reads
    }
    const std::size_t before = used.json().size();
    for (Machine* m : {&fresh, &used}) {
      blocks(*m, {lathe ? "G01 X10. Z-2. F0.2 S500" : "G01 X10. Z-2. F200.",
                  "X15.", "G02 X25. Z3. R5."});
      mbrt_finish(m->ctx(), MBRT_END_M02_M30);
    }
    const std::vector<std::string> after(used.json().begin() + before,
                                         used.json().end());
    EXPECT_EQ(after, fresh.json()) << profile;
  }
}

} // namespace
} // namespace mbc::test
