// What embedders use beyond the sinks: the alarm callback and the toolpath
// buffer.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

void collect(void* user, const char* data, size_t size) {
  static_cast<std::string*>(user)->append(data, size);
}

TEST(RuntimeEmbedding, AlarmSinkGetsTheReportOnce) {
  Machine m;
  std::string reports;
  mbrt_set_alarm_sink(m.ctx(), collect, &reports);
  mbrt_begin_block(m.ctx(), "cycle.nc", 4);
  EXPECT_EQ(m.write(0, 1), status(AlarmId::WriteProtectedVariable));
  EXPECT_EQ(m.write(0, 1), status(AlarmId::WriteProtectedVariable));
  EXPECT_EQ(reports,
            "cycle.nc:4: alarm PS0116: WRITE PROTECTED VARIABLE: #0\n");
}

TEST(RuntimeEmbedding, BufferKeepsTheMotionsOfOneRun) {
  Machine m;
  mbrt_buffer_motions(m.ctx(), 1);
  ASSERT_EQ(m.block("G01 X10. F100"), 0);
  ASSERT_EQ(m.block("G00 Y5."), 0);
  size_t count = 0;
  const mbrt_motion* motions = mbrt_buffered_motions(m.ctx(), &count);
  ASSERT_EQ(count, 2U);
  EXPECT_EQ(motions[0].kind, MBRT_MOTION_LINEAR);
  EXPECT_EQ(motions[0].end[0], 10.0);
  EXPECT_EQ(motions[1].end[1], 5.0);
  EXPECT_STREQ(motions[1].program, "O1000");
  mbrt_start(m.ctx(), "O2000");
  mbrt_buffered_motions(m.ctx(), &count);
  EXPECT_EQ(count, 0U);
}

TEST(RuntimeEmbedding, InterruptStopsTheNextBlockOfThisRunOnly) {
  Machine m;
  ASSERT_EQ(m.block("G00 X1.", 1), 0);
  mbrt_interrupt(m.ctx());
  EXPECT_EQ(m.block("G00 X2.", 2), status(AlarmId::Interrupted));
  EXPECT_EQ(m.report(), "test.nc:2: alarm MBC0004: INTERRUPTED: the run was "
                        "stopped before this block\n");
  EXPECT_EQ(m.motions().size(), 1U);
  mbrt_start(m.ctx(), "O1000");
  EXPECT_EQ(m.block("G00 X2.", 2), 0);
}

TEST(RuntimeEmbedding, OutOfMemoryStopsTheNextBlockOfThisRunOnly) {
  Machine m;
  ASSERT_EQ(m.block("G00 X1.", 1), 0);
  mbrt_out_of_memory(m.ctx());
  EXPECT_EQ(m.block("G00 X2.", 2), status(AlarmId::OutOfMemory));
  EXPECT_EQ(m.report(), "test.nc:2: alarm MBC0005: OUT OF MEMORY: memory ran "
                        "out; the run was stopped before this block\n");
  EXPECT_EQ(m.motions().size(), 1U);
  mbrt_start(m.ctx(), "O1000");
  EXPECT_EQ(m.block("G00 X2.", 2), 0);
}

TEST(RuntimeEmbedding, ProgramNamesOutliveTheirCalls) {
  Machine m;
  mbrt_buffer_motions(m.ctx(), 1);
  ASSERT_EQ(mbrt_call_sub(m.ctx(), "O0042"), 0);
  ASSERT_EQ(m.block("G01 X1. F100"), 0);
  mbrt_return(m.ctx());
  size_t count = 0;
  const mbrt_motion* motions = mbrt_buffered_motions(m.ctx(), &count);
  ASSERT_EQ(count, 1U);
  EXPECT_STREQ(motions[0].program, "O0042");
}

} // namespace
} // namespace mbc::test
