// Calls through the C ABI: G65 argument mapping (specification I and II,
// decimal-point scaling), local levels, M98 sharing locals, nesting limits.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

TEST(RuntimeCalls, SpecificationOneMapsEveryLetter) {
  Machine m;
  ASSERT_EQ(m.callMacro("O9000", "A1. B2. C3. I4. J5. K6. D7. E8. F9. H11. "
                                 "M13. Q17. R18. S19. T20. U21. V22. W23. "
                                 "X24. Y25. Z26."),
            0);
  for (int local : {1,  2,  3,  4,  5,  6,  7,  8,  9,  11, 13,
                    17, 18, 19, 20, 21, 22, 23, 24, 25, 26}) {
    EXPECT_EQ(m.read(local), local) << "#" << local;
  }
  for (int local : {10, 12, 14, 15, 16, 27, 33}) {
    EXPECT_TRUE(isVacant(m.read(local))) << "#" << local;
  }
}

TEST(RuntimeCalls, FanucMixedExample) {
  // G65 A1.0 B2.0 I-3.0 I4.0 D5.0 P1000 (spec §5.4).
  Machine m;
  ASSERT_EQ(m.callMacro("O1000", "A1.0 B2.0 I-3.0 I4.0 D5.0"), 0);
  EXPECT_EQ(m.read(1), 1.0);
  EXPECT_EQ(m.read(2), 2.0);
  EXPECT_TRUE(isVacant(m.read(3)));
  EXPECT_EQ(m.read(4), -3.0);
  EXPECT_TRUE(isVacant(m.read(5)));
  EXPECT_TRUE(isVacant(m.read(6)));
  EXPECT_EQ(m.read(7), 5.0);
}

TEST(RuntimeCalls, SpecificationTwoSets) {
  Machine m;
  ASSERT_EQ(m.callMacro("O9000", "I1. J2. K3. I4. J5. K6. J7. I8. K9."), 0);
  EXPECT_EQ(m.read(4), 1.0);
  EXPECT_EQ(m.read(5), 2.0);
  EXPECT_EQ(m.read(6), 3.0);
  EXPECT_EQ(m.read(7), 4.0);
  EXPECT_EQ(m.read(8), 5.0);
  EXPECT_EQ(m.read(9), 6.0);
  EXPECT_EQ(m.read(11), 7.0);        // set 3 J
  EXPECT_EQ(m.read(13), 8.0);        // I out of order: set 4
  EXPECT_EQ(m.read(15), 9.0);        // set 4 K
  EXPECT_TRUE(isVacant(m.read(10))); // set 3 I
}

TEST(RuntimeCalls, TenSetsReachLocal33) {
  Machine m;
  ASSERT_EQ(m.callMacro("O9000", "K1. K2. K3. K4. K5. K6. K7. K8. K9. K10."),
            0);
  EXPECT_EQ(m.read(6), 1.0);
  EXPECT_EQ(m.read(33), 10.0);
  Machine n;
  EXPECT_EQ(n.callMacro("O9000", "I1. I2. I3. I4. I5. I6. I7. I8. I9. I10. "
                                 "I11."),
            status(AlarmId::MacroStatementFormat));
  EXPECT_EQ(mbrt_call_depth(n.ctx()), 0);
}

TEST(RuntimeCalls, ForbiddenArgumentLetters) {
  Machine g;
  EXPECT_EQ(g.callMacro("O9000", "G1"), status(AlarmId::GAsArgument));
  for (const char* args : {"L2", "N1", "O1", "P1000"}) {
    Machine m;
    EXPECT_EQ(m.callMacro("O9000", args), status(AlarmId::MacroStatementFormat))
        << args;
  }
}

TEST(RuntimeCalls, LiteralsWithoutDecimalPointAreScaled) {
  Machine m;
  ASSERT_EQ(m.callMacro("O9000", "X10 Z-25 I5 R2 Q3 F100 S500 A7 X=2"), 0);
  EXPECT_EQ(m.read(24), 2.0); // the later X wins
  EXPECT_EQ(m.read(26), -0.025);
  EXPECT_EQ(m.read(4), 0.005);
  EXPECT_EQ(m.read(18), 0.002);
  EXPECT_EQ(m.read(17), 0.003);
  EXPECT_EQ(m.read(9), 100.0);
  EXPECT_EQ(m.read(19), 500.0);
  EXPECT_EQ(m.read(1), 7.0); // A is no axis of this machine
}

// A literal without decimal point counts the least increment of its
// address: 0.0001 inch on X, 0.001 degree on the rotary A whatever G20.
TEST(RuntimeCalls, InchAndFourthAxisScaling) {
  Machine m(R"({"axes": ["X", "Y", "Z", "A"], "units": "inch"})");
  ASSERT_EQ(m.callMacro("O9000", "X10 A7"), 0);
  EXPECT_EQ(m.read(24), 0.001);
  EXPECT_EQ(m.read(1), 0.007);
  mbrt_num value = 0;
  ASSERT_EQ(mbrt_adp(m.ctx(), 1, &value), 0);
  EXPECT_EQ(value, 7.0);
}

TEST(RuntimeCalls, DecimalPointInputKeepsLiterals) {
  Machine m(R"({"parameters": {"3401": 1}})");
  ASSERT_EQ(m.callMacro("O9000", "X10"), 0);
  EXPECT_EQ(m.read(24), 10.0);
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_adp(m.ctx(), 24, &value), 0);
  EXPECT_EQ(value, 10.0);
}

TEST(RuntimeCalls, MacroCallHasItsOwnLocals) {
  Machine m;
  m.write(1, 11.0);
  m.write(2, 22.0);
  ASSERT_EQ(m.callMacro("O9000", "A5."), 0);
  EXPECT_EQ(mbrt_call_depth(m.ctx()), 1);
  EXPECT_EQ(m.read(1), 5.0);
  EXPECT_TRUE(isVacant(m.read(2)));
  m.write(2, 99.0);
  mbrt_return(m.ctx());
  EXPECT_EQ(mbrt_call_depth(m.ctx()), 0);
  EXPECT_EQ(m.read(1), 11.0);
  EXPECT_EQ(m.read(2), 22.0);
}

TEST(RuntimeCalls, SubprogramSharesLocals) {
  Machine m;
  m.write(1, 11.0);
  ASSERT_EQ(mbrt_call_sub(m.ctx(), "O2000"), 0);
  EXPECT_EQ(m.read(1), 11.0);
  EXPECT_EQ(m.read(4115), 2000.0);
  m.write(1, 12.0);
  mbrt_return(m.ctx());
  EXPECT_EQ(m.read(1), 12.0);
  EXPECT_EQ(m.read(4115), 1000.0);
}

TEST(RuntimeCalls, MacroNestingLimit) {
  Machine m;
  for (int level = 1; level <= 5; ++level) {
    ASSERT_EQ(m.callMacro("O9000", ""), 0) << level;
  }
  EXPECT_EQ(m.callMacro("O9000", ""), status(AlarmId::TooManyMacroNesting));
  EXPECT_EQ(mbrt_call_depth(m.ctx()), 5);
}

TEST(RuntimeCalls, SubprogramNestingLimit) {
  Machine m;
  for (int level = 1; level <= 10; ++level) {
    ASSERT_EQ(mbrt_call_sub(m.ctx(), "O2000"), 0) << level;
  }
  EXPECT_EQ(mbrt_call_sub(m.ctx(), "O2000"),
            status(AlarmId::TooManySubMacroNesting));
}

TEST(RuntimeCalls, TotalNestingLimit) {
  Machine m(R"({"limits": {"total_nesting": 3}})");
  ASSERT_EQ(m.callMacro("O9000", ""), 0);
  ASSERT_EQ(mbrt_call_sub(m.ctx(), "O2000"), 0);
  ASSERT_EQ(m.callMacro("O9001", ""), 0);
  EXPECT_EQ(m.callMacro("O9002", ""), status(AlarmId::TooManySubMacroNesting));
  Machine n(R"({"limits": {"total_nesting": 1}})");
  ASSERT_EQ(mbrt_call_sub(n.ctx(), "O2000"), 0);
  EXPECT_EQ(mbrt_call_sub(n.ctx(), "O2001"),
            status(AlarmId::TooManySubMacroNesting));
}

TEST(RuntimeCalls, MainProgramArguments) {
  Machine m;
  const std::vector<mbrt_word> args = parseWords("X10 I1. I2. D4.");
  ASSERT_EQ(mbrt_set_main_args(m.ctx(), args.data(), args.size()), 0);
  EXPECT_EQ(mbrt_call_depth(m.ctx()), 0);
  EXPECT_EQ(m.read(24), 0.01);
  EXPECT_EQ(m.read(4), 1.0);
  EXPECT_EQ(m.read(7), 4.0);
  const std::vector<mbrt_word> bad = parseWords("P1");
  EXPECT_EQ(mbrt_set_main_args(m.ctx(), bad.data(), bad.size()),
            status(AlarmId::MacroStatementFormat));
  EXPECT_EQ(m.read(24), 0.01);
  // A host's lower-case letter is the argument's, as Python's x= is.
  Machine lower;
  std::vector<mbrt_word> host = parseWords("X1. D4.");
  host[0].letter = 'x';
  host[1].letter = 'd';
  ASSERT_EQ(mbrt_set_main_args(lower.ctx(), host.data(), host.size()), 0);
  EXPECT_EQ(lower.read(24), 1.0);
  EXPECT_EQ(lower.read(7), 4.0);
  host[0].letter = 'p';
  EXPECT_EQ(mbrt_set_main_args(lower.ctx(), host.data(), host.size()),
            status(AlarmId::MacroStatementFormat));
}

TEST(RuntimeCalls, ReturnInMainProgramIsHarmless) {
  Machine m;
  mbrt_return(m.ctx());
  EXPECT_EQ(mbrt_call_depth(m.ctx()), 0);
  EXPECT_EQ(m.write(1, 1.0), 0);
}

} // namespace
} // namespace mbc::test
