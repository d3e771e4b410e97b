// The calls NC blocks ask for (runtime/src/machine/block_calls.cpp):
// G66/G66.1/G67, custom G and M codes, M/T/S/B code subprograms, and the rules
// that keep a code from calling inside its own program.
#include "runtime_test_support.h"

namespace mbc::test {

namespace {

constexpr const char* kCodes = R"({"parameters": {
  "6050": 100, "6051": -101, "6071": 6, "6080": 50, "6001": 32, "6007": 48}})";

std::string letters(const mbrt_flow& flow) {
  std::string out;
  for (size_t i = 0; i < flow.arg_count; ++i) {
    out += flow.args[i].letter;
  }
  return out;
}

} // namespace

TEST(RuntimeBlockCalls, G66CallsAfterEachMove) {
  Machine m;
  ASSERT_EQ(m.block("G66 P9050 L2 Z-15. R2."), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  EXPECT_EQ(m.read(4012), 66.0);
  EXPECT_TRUE(m.motions().empty()); // the G66 block's words are arguments
  ASSERT_EQ(m.block("G00 X10. Y10."), 0);
  EXPECT_EQ(m.motions().size(), 1u);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_CALL);
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_MODAL);
  EXPECT_EQ(m.flow().program, 9050);
  EXPECT_EQ(m.flow().repeat, 2);
  EXPECT_EQ(letters(m.flow()), "ZR");
  ASSERT_EQ(m.block("F100"), 0); // no axis word, no call
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  ASSERT_EQ(m.block("G67"), 0);
  EXPECT_EQ(m.read(4012), 67.0);
  ASSERT_EQ(m.block("G00 X20."), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
}

TEST(RuntimeBlockCalls, G66DoesNotCallInsideItsOwnMacro) {
  Machine m;
  ASSERT_EQ(m.block("G66 P9050 A1."), 0);
  ASSERT_EQ(m.block("X1."), 0);
  ASSERT_EQ(mbrt_call(m.ctx(), "O9050", m.flow().call_kind, m.flow().args,
                      m.flow().arg_count),
            0);
  EXPECT_EQ(m.read(1), 1.0);
  ASSERT_EQ(m.block("X2."), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  // A G66 of the macro's own calls after its moves; G67 cancels it first.
  ASSERT_EQ(m.block("G66 P9051"), 0);
  ASSERT_EQ(m.block("X3."), 0);
  EXPECT_EQ(m.flow().program, 9051);
  ASSERT_EQ(m.block("G67"), 0);
  mbrt_return(m.ctx());
  ASSERT_EQ(m.block("X4."), 0);
  EXPECT_EQ(m.flow().program, 9050);
}

TEST(RuntimeBlockCalls, G661PassesEveryBlockAsArguments) {
  Machine m;
  ASSERT_EQ(m.block("G66.1 P9060 A5."), 0);
  EXPECT_EQ(m.read(4012), 66.1);
  // The G66.1 block itself calls like G65.
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_CALL);
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_MODAL);
  EXPECT_EQ(letters(m.flow()), "A");
  ASSERT_EQ(m.block("G01 X10. P3 L2"), 0);
  EXPECT_TRUE(m.motions().empty()); // the block is not executed
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_CALL);
  EXPECT_EQ(letters(m.flow()), "GXPL");
  ASSERT_EQ(mbrt_call(m.ctx(), "O9060", m.flow().call_kind, m.flow().args,
                      m.flow().arg_count),
            0);
  EXPECT_EQ(m.read(10), 1.0); // G
  EXPECT_EQ(m.read(24), 10.0);
  EXPECT_EQ(m.read(16), 3.0); // P
  EXPECT_EQ(m.read(12), 2.0); // L
  mbrt_return(m.ctx());
  ASSERT_EQ(m.block("G67"), 0);
  ASSERT_EQ(m.block("G01 X10. F100."), 0);
  EXPECT_EQ(m.motions().size(), 1u);
}

TEST(RuntimeBlockCalls, G66NeedsP) {
  Machine m;
  EXPECT_EQ(m.block("G66 X1.", 4), status(AlarmId::ProgramNotFound));
  EXPECT_EQ(m.report(),
            "test.nc:4: alarm PS0076: PROGRAM NOT FOUND: G66 without P\n");
  Machine n;
  EXPECT_EQ(n.block("G66 P9000 G01"), status(AlarmId::GAsArgument));
}

TEST(RuntimeBlockCalls, CustomGCodeCallsItsMacro) {
  Machine m(kCodes);
  ASSERT_EQ(m.block("G100 X5. Y6. L3"), 0);
  EXPECT_TRUE(m.motions().empty());
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_CALL);
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_CODE_MACRO);
  EXPECT_EQ(m.flow().program, 9010);
  EXPECT_EQ(m.flow().repeat, 3);
  EXPECT_EQ(letters(m.flow()), "XY");
  // Inside, G100 is an ordinary (here unknown) G code.
  ASSERT_EQ(mbrt_call(m.ctx(), "O9010", m.flow().call_kind, m.flow().args,
                      m.flow().arg_count),
            0);
  EXPECT_EQ(m.block("G100 X1."), status(AlarmId::ImproperGCode));
}

TEST(RuntimeBlockCalls, NegativeParameterMakesACustomGCodeModal) {
  Machine m(kCodes);
  ASSERT_EQ(m.block("G101 R3."), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  EXPECT_EQ(m.read(4012), 66.0);
  ASSERT_EQ(m.block("X1."), 0);
  EXPECT_EQ(m.flow().program, 9011);
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_MODAL);
  EXPECT_EQ(letters(m.flow()), "R");
}

TEST(RuntimeBlockCalls, CustomMCodeCallsItsMacro) {
  Machine m(kCodes);
  ASSERT_EQ(m.block("X1. M50 A2."), 0);
  EXPECT_TRUE(m.motions().empty()); // a macro call executes nothing else
  EXPECT_EQ(m.flow().program, 9020);
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_CODE_MACRO);
  EXPECT_EQ(letters(m.flow()), "XA");
}

TEST(RuntimeBlockCalls, CodeSubprogramsRunAfterTheBlock) {
  Machine m(kCodes);
  ASSERT_EQ(m.block("G00 X1. M06"), 0);
  EXPECT_EQ(m.motions().size(), 1u);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_CALL);
  EXPECT_EQ(m.flow().call_kind, MBRT_CALL_CODE_SUB);
  EXPECT_EQ(m.flow().program, 9001);
  ASSERT_EQ(m.block("T12"), 0);
  EXPECT_EQ(m.flow().program, 9000);
  EXPECT_EQ(m.read(149), 12.0);
  EXPECT_EQ(m.read(4120), 12.0);
  ASSERT_EQ(m.block("S3000"), 0);
  EXPECT_EQ(m.flow().program, 9029);
  EXPECT_EQ(m.read(147), 3000.0);
  ASSERT_EQ(m.block("B90"), 0);
  EXPECT_EQ(m.flow().program, 9028);
  EXPECT_EQ(m.read(146), 90.0);
  // Inside a program a code called, codes do not call.
  ASSERT_EQ(mbrt_call(m.ctx(), "O9028", MBRT_CALL_CODE_SUB, nullptr, 0), 0);
  ASSERT_EQ(m.block("T3 M06"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  EXPECT_EQ(m.read(149), 12.0);
}

TEST(RuntimeBlockCalls, CodesDoNotCallWithoutTheirParameters) {
  Machine m;
  ASSERT_EQ(m.block("T12 M06 S100"), 0);
  EXPECT_EQ(m.flow().kind, MBRT_FLOW_NEXT);
  EXPECT_EQ(m.block("G100"), status(AlarmId::ImproperGCode));
}

TEST(RuntimeBlockCalls, TwoCallsInOneBlockAlarm) {
  Machine m(kCodes);
  EXPECT_EQ(m.block("T1 M06", 7), status(AlarmId::Unsupported));
  EXPECT_EQ(m.report(), "test.nc:7: alarm MBC0001: NOT SUPPORTED BY MBC YET: "
                        "two calls in one block (M06 and T1)\n");
  Machine n(kCodes);
  EXPECT_EQ(n.block("M98 P100 M06"), status(AlarmId::Unsupported));
}

TEST(RuntimeBlockCalls, ProfilesCannotRedefineTheControlsCodes) {
  char err[256] = "";
  EXPECT_EQ(mbrt_create(R"({"parameters": {"6050": 81}})", err, sizeof err),
            nullptr);
  EXPECT_STREQ(err, "machine profile: \"parameters.6050\" must not be a G code "
                    "mbc executes (G81)");
  // A code of the control's list that mbc does not execute (G37, automatic
  // tool length measurement) may be given to a probing macro.
  Machine probing(R"({"parameters": {"6050": 37}})");
  ASSERT_EQ(probing.block("G37 Z-10."), 0);
  EXPECT_EQ(probing.flow().kind, MBRT_FLOW_CALL);
  EXPECT_EQ(probing.flow().program, 9010);
  EXPECT_EQ(mbrt_create(R"({"parameters": {"6071": 30}})", err, sizeof err),
            nullptr);
  EXPECT_STREQ(err,
               "machine profile: \"parameters.6071\" must not be M30 (0 = no "
               "code)");
  EXPECT_EQ(mbrt_create(R"({"parameters": {"6050": 1.5}})", err, sizeof err),
            nullptr);
  EXPECT_STREQ(err, "machine profile: \"parameters.6050\" must be a whole "
                    "number from -9999 to 9999");
}

} // namespace mbc::test
