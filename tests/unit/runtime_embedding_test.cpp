// What embedders use beyond the sinks: the alarm callback, the toolpath
// buffer, what a sink may not call, the set commons.
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

// A host's call after a run is the host's: its alarm is not blamed on the
// run's last block.
TEST(RuntimeEmbedding, AHostsCallAfterARunIsReportedAsTheHosts) {
  Machine m;
  const mbrt_program face{"O1", 1,
                          [](mbrt_ctx* ctx, void*, mbrt_flow*) -> mbrt_status {
                            return mbrt_begin_block(ctx, "face.nc", 24);
                          }};
  ASSERT_EQ(mbrt_run_main(m.ctx(), &face, nullptr, 0), 0);
  EXPECT_EQ(m.write(5001, 1.0), MBRT_ALARM_WriteProtectedVariable);
  EXPECT_EQ(m.report(), "alarm PS0116: WRITE PROTECTED VARIABLE: #5001 "
                        "(called by the host, outside any block)\n");
}

/// A motion sink that calls back into its context as a careless host would.
struct Reentry {
  mbrt_ctx* ctx;
  int motions = 0;
  mbrt_status run = 0;
};

TEST(RuntimeEmbedding, CallsFromInsideASinkAreRefused) {
  Machine m;
  Reentry reentry{m.ctx()};
  mbrt_set_motion_sink(
      m.ctx(),
      [](void* user, const mbrt_motion*) {
        auto& r = *static_cast<Reentry*>(user);
        ++r.motions;
        mbrt_reset(r.ctx);
        const mbrt_program other{"O9", 9, nullptr};
        r.run = mbrt_run_main(r.ctx, &other, nullptr, 0);
        mbrt_destroy(r.ctx);
      },
      &reentry);
  ASSERT_EQ(m.block("G01 X10. F100", 1), 0); // the block ends as it began
  EXPECT_EQ(reentry.motions, 1);
  EXPECT_EQ(reentry.run, MBRT_ALARM_CalledFromSink);
  EXPECT_EQ(m.read(5001), 10.0); // not reset under the block's feet
  EXPECT_EQ(m.block("G01 X20.", 2), MBRT_ALARM_CalledFromSink);
  EXPECT_EQ(m.report(),
            "test.nc:2: alarm MBC0007: CALLED FROM A SINK: mbrt_reset was "
            "called from inside a sink (a motion, text or alarm callback); "
            "the run was stopped before this block\n");
  EXPECT_EQ(reentry.motions, 1);
  mbrt_set_motion_sink(m.ctx(), nullptr, nullptr);
  mbrt_start(m.ctx(), "O1000"); // from outside: the next run goes on
  EXPECT_EQ(m.block("G01 X20. F100", 1), 0);
  EXPECT_EQ(m.read(5001), 20.0);
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

TEST(RuntimeEmbedding, SetCommonsInNumberOrderSnprintfStyle) {
  Machine m;
  ASSERT_EQ(m.write(999, -1), 0);
  ASSERT_EQ(m.write(101, 3), 0);
  ASSERT_EQ(m.write(102, 0), 0); // zero is a value, not vacant
  EXPECT_EQ(mbrt_set_commons(m.ctx(), nullptr, nullptr, 0), 3U);
  int numbers[3] = {};
  mbrt_num values[3] = {};
  EXPECT_EQ(mbrt_set_commons(m.ctx(), numbers, values, 2), 3U);
  EXPECT_EQ(numbers[0], 101);
  EXPECT_EQ(numbers[1], 102);
  EXPECT_EQ(numbers[2], 0); // past the capacity: untouched
  mbrt_set_commons(m.ctx(), numbers, values, 3);
  EXPECT_EQ(numbers[2], 999);
  EXPECT_EQ(values[0], 3.0);
  EXPECT_EQ(values[2], -1.0);
}

} // namespace
} // namespace mbc::test
