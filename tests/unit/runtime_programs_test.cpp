// Compiled programs through the C ABI: program tables, calls with repeats
// and M99 P, running a program as the main one, reset, block skip switches
// and the storage compiled code addresses directly.
#include <mbc/addresses.h>
#include <mbc/arith.h>

#include <cmath>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

// A body that counts its runs in #100, reads #1 into #101 and leaves by
// M99 P<#102> when #102 is set.
mbrt_status countingBody(mbrt_ctx* ctx, void*, mbrt_flow* leave) {
  mbrt_num runs, arg, seq;
  mbrt_read_var(ctx, 100, &runs);
  mbrt_write_var(ctx, 100, isVacant(runs) ? 1 : runs + 1, nullptr);
  mbrt_read_var(ctx, 1, &arg);
  mbrt_write_var(ctx, 101, arg, nullptr);
  mbrt_read_var(ctx, 102, &seq);
  if (!isVacant(seq)) {
    leave->has_seq = 1;
    leave->seq = seq;
  }
  return 0;
}

mbrt_status stoppingBody(mbrt_ctx* ctx, void*, mbrt_flow*) {
  mbrt_finish(ctx, MBRT_END_M02_M30);
  return MBRT_STOP;
}

const mbrt_program kPrograms[] = {
    {"O0012", 12, countingBody}, {"<CYCLE>", kFirstNamedProgram, stoppingBody}};
const mbrt_program_table kTable = {kPrograms, 2};

TEST(RuntimePrograms, FindsByNumberAndName) {
  EXPECT_EQ(mbrt_find_program(&kTable, 12, nullptr), &kPrograms[0]);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "O12"), &kPrograms[0]);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "o0012"), &kPrograms[0]);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "<CYCLE>"), &kPrograms[1]);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "cycle"), &kPrograms[1]);
  EXPECT_EQ(mbrt_find_program(&kTable, kFirstNamedProgram, nullptr),
            &kPrograms[1]);
  EXPECT_EQ(mbrt_find_program(&kTable, 13, nullptr), nullptr);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "O12X"), nullptr);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "O99999999999"), nullptr);
  EXPECT_EQ(mbrt_find_program(&kTable, -1, "MAIN"), nullptr);
}

// A call by name carries its program's number; the trace shows the name.
TEST(RuntimePrograms, TracesCallsByTheirNames) {
  Machine m;
  std::string trace;
  mbrt_set_trace_sink(
      m.ctx(),
      [](void* user, const char* data, size_t size) {
        static_cast<std::string*>(user)->append(data, size);
      },
      &trace);
  mbrt_name_programs(m.ctx(), &kTable);
  ASSERT_EQ(m.block("M98 P100000000 L2", 7), 0);
  EXPECT_EQ(m.flow().program, kFirstNamedProgram);
  EXPECT_EQ(m.flow().repeat, 2);
  ASSERT_EQ(m.block("G4 P100000000", 8), 0); // no call: a time
  mbrt_trace_call(m.ctx(), kFirstNamedProgram, 1, nullptr, 0);
  EXPECT_EQ(trace, "test.nc:7: M98 <CYCLE> L2\n"
                   "test.nc:8: G4 P100000000\n"
                   "test.nc:8: G65 <CYCLE> L1\n");
}

// A P beyond every program number (an int once took it, undefined) is
// PS0076, as a call of a program that does not exist.
TEST(RuntimePrograms, HugePIsProgramNotFound) {
  for (const char* block : {"M98 P99999999999", "G66 P-99999999999 A1."}) {
    Machine m;
    EXPECT_EQ(m.block(block), status(AlarmId::ProgramNotFound)) << block;
    EXPECT_NE(m.report().find("PS0076"), std::string::npos) << m.report();
  }
}

// A 4-digit control reads a long M98 P as repeats and program, but no
// packed P reaches a named program's number.
TEST(RuntimePrograms, NamedProgramsPassThe4DigitRules) {
  Machine m(R"({"program_number_digits": 4})");
  ASSERT_EQ(m.block("M98 P100000000"), 0);
  EXPECT_EQ(m.flow().program, kFirstNamedProgram);
  EXPECT_EQ(m.flow().repeat, 1);
  ASSERT_EQ(m.block("M98 P20012"), 0);
  EXPECT_EQ(m.flow().program, 12);
  EXPECT_EQ(m.flow().repeat, 2);
}

TEST(RuntimePrograms, CallRepeatsWithArgumentsAndLevels) {
  Machine m;
  const std::vector<mbrt_word> args = parseWords("A=7");
  mbrt_flow out{};
  ASSERT_EQ(mbrt_run_call(m.ctx(), "O0012", 1, args.data(), args.size(), 3, 0,
                          countingBody, nullptr, &out),
            0);
  EXPECT_EQ(m.read(100), 3.0);
  EXPECT_EQ(m.read(101), 7.0);
  EXPECT_TRUE(isVacant(m.read(1))); // the caller's level is back
  EXPECT_EQ(mbrt_call_depth(m.ctx()), 0);
  EXPECT_EQ(out.has_seq, 0);
}

TEST(RuntimePrograms, M99PStopsTheRepeats) {
  Machine m;
  m.write(102, 40);
  mbrt_flow out{};
  ASSERT_EQ(mbrt_run_call(m.ctx(), "O0012", 0, nullptr, 0, 5, 0, countingBody,
                          nullptr, &out),
            0);
  EXPECT_EQ(m.read(100), 1.0);
  EXPECT_EQ(out.has_seq, 1);
  EXPECT_EQ(out.seq, 40.0);
}

TEST(RuntimePrograms, NoRepeatNoCall) {
  Machine m;
  mbrt_flow out{};
  EXPECT_EQ(mbrt_run_call(m.ctx(), "O0012", 1, nullptr, 0, 0, 0, countingBody,
                          nullptr, &out),
            0);
  EXPECT_TRUE(isVacant(m.read(100)));
}

TEST(RuntimePrograms, RunMainSetsArgumentsAndMapsTheStop) {
  Machine m;
  const std::vector<mbrt_word> args = parseWords("A5");
  EXPECT_EQ(mbrt_run_main(m.ctx(), &kPrograms[0], args.data(), args.size()), 0);
  EXPECT_EQ(m.read(101), 5.0); // A is not an axis: no scaling
  EXPECT_EQ(mbrt_run_main(m.ctx(), &kPrograms[1], nullptr, 0), 0);
  EXPECT_EQ(m.read(3901), 1.0);
}

TEST(RuntimePrograms, ResetRestoresTheProfile) {
  Machine m(R"({"variables": {"500": 2.5}})");
  m.write(500, 9);
  m.write(100, 1);
  mbrt_reset(m.ctx());
  EXPECT_EQ(m.read(500), 2.5);
  EXPECT_TRUE(isVacant(m.read(100)));
}

TEST(RuntimePrograms, BlockSkipSwitches) {
  Machine plain;
  EXPECT_EQ(mbrt_skip_switch(plain.ctx(), 1), 0);
  mbrt_set_block_skip(plain.ctx(), 1U << 3);
  EXPECT_EQ(mbrt_skip_switch(plain.ctx(), 3), 1);
  EXPECT_EQ(mbrt_skip_switch(plain.ctx(), 1), 0);
  Machine skipping(R"({"block_skip": true})");
  EXPECT_EQ(mbrt_skip_switch(skipping.ctx(), 1), 1);
}

TEST(RuntimePrograms, CompiledStorageIsTheVariables) {
  Machine m;
  m.write(5, 1.5);
  m.write(150, 2.5);
  EXPECT_EQ(mbrt_current_level(m.ctx())->value[4], 1.5);
  EXPECT_EQ(mbrt_common_base(m.ctx())[150], 2.5);
  mbrt_block_state* b = mbrt_block_state_of(m.ctx());
  mbrt_set_max_blocks(m.ctx(), 2);
  EXPECT_EQ(m.block("G00", 7), 0);
  EXPECT_EQ(b->line, 7);
  EXPECT_EQ(b->blocks, 1U);
  EXPECT_EQ(b->max_blocks, 2U);
  EXPECT_EQ(mbrt_block_limit(m.ctx()), status(AlarmId::ExecutionLimit));
}

TEST(RuntimePrograms, CompiledArithmeticRaisesAlarms) {
  Machine m;
  double out = 0;
  EXPECT_EQ(mbrt_binary(m.ctx(), static_cast<int>(BinOp::Mod), 7, 4, &out), 0);
  EXPECT_EQ(out, 3.0);
  EXPECT_EQ(mbrt_binary(m.ctx(), static_cast<int>(BinOp::Mod), 7, 0, &out),
            status(AlarmId::ZeroDivide));
  EXPECT_EQ(mbrt_alarm(m.ctx()), static_cast<int>(AlarmId::ZeroDivide));
  Machine n;
  EXPECT_EQ(mbrt_builtin(n.ctx(), static_cast<int>(Builtin::Sin), 30, 0, &out),
            0);
  EXPECT_EQ(out, 0.5);
  EXPECT_EQ(mbrt_round_address(n.ctx(), 'X', 1.23456, &out), 0);
  EXPECT_DOUBLE_EQ(out, 1.235);
  // Rounded to zero it is +0, as every macro value (a -0 came out as Y-0
  // under the JIT, whose subtraction keeps the sign that the interpreter's
  // dropped).
  EXPECT_EQ(mbrt_round_address(n.ctx(), 'Y', -0.000001, &out), 0);
  EXPECT_EQ(out, 0.0);
  EXPECT_FALSE(std::signbit(out));
}

} // namespace
} // namespace mbc::test
