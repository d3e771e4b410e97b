// Alarms and their report: location, message, detail, the call stack, the
// first alarm winning, snprintf-style truncation; the run's statistics.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

TEST(RuntimeAlarm, ReportWithCallStack) {
  Machine m;
  mbrt_begin_block(m.ctx(), "main.nc", 5);
  ASSERT_EQ(m.callMacro("O9100", "A1."), 0);
  mbrt_begin_block(m.ctx(), "main.nc", 43);
  ASSERT_EQ(mbrt_call_sub(m.ctx(), "O9200"), 0);
  mbrt_begin_block(m.ctx(), "sub.nc", 50);
  EXPECT_EQ(mbrt_raise(m.ctx(), status(AlarmId::ZeroDivide), nullptr),
            status(AlarmId::ZeroDivide));
  EXPECT_EQ(mbrt_alarm(m.ctx()), status(AlarmId::ZeroDivide));
  EXPECT_EQ(m.report(), "sub.nc:50: alarm PS0112: ZERO DIVIDE\n"
                        "  in O9200 called from main.nc:43\n"
                        "  in O9100 called from main.nc:5\n");
  // The report is a snapshot: leaving the calls does not change it.
  mbrt_return(m.ctx());
  mbrt_return(m.ctx());
  EXPECT_NE(m.report().find("O9100"), std::string::npos);
}

TEST(RuntimeAlarm, DetailIsAppended) {
  Machine m;
  mbrt_begin_block(m.ctx(), "p.nc", 9);
  mbrt_raise(m.ctx(), status(AlarmId::IllegalMacroSequenceNumber), "N100");
  EXPECT_EQ(m.report(),
            "p.nc:9: alarm PS0128: ILLEGAL MACRO SEQUENCE NUMBER: N100\n");
}

TEST(RuntimeAlarm, FirstAlarmIsKept) {
  Machine m;
  mbrt_begin_block(m.ctx(), "p.nc", 1);
  mbrt_raise(m.ctx(), status(AlarmId::ZeroDivide), nullptr);
  mbrt_begin_block(m.ctx(), "p.nc", 2);
  mbrt_raise(m.ctx(), status(AlarmId::FloatOverflow), nullptr);
  EXPECT_EQ(mbrt_alarm(m.ctx()), status(AlarmId::ZeroDivide));
  EXPECT_EQ(m.report(), "p.nc:1: alarm PS0112: ZERO DIVIDE\n");
}

TEST(RuntimeAlarm, ReportIsTruncatedLikeSnprintf) {
  Machine m;
  mbrt_begin_block(m.ctx(), "p.nc", 1);
  mbrt_raise(m.ctx(), status(AlarmId::ZeroDivide), nullptr);
  char small[8];
  const size_t length = mbrt_alarm_report(m.ctx(), small, sizeof small);
  EXPECT_EQ(length, std::string("p.nc:1: alarm PS0112: ZERO DIVIDE\n").size());
  EXPECT_STREQ(small, "p.nc:1:");
}

TEST(RuntimeAlarm, NoAlarmNoReport) {
  Machine m;
  EXPECT_EQ(mbrt_alarm(m.ctx()), 0);
  EXPECT_EQ(m.report(), "");
}

TEST(RuntimeAlarm, StartClearsTheAlarm) {
  Machine m;
  mbrt_raise(m.ctx(), status(AlarmId::ZeroDivide), nullptr);
  mbrt_start(m.ctx(), "O2");
  EXPECT_EQ(mbrt_alarm(m.ctx()), 0);
}

TEST(RuntimeAlarm, TraceLines) {
  Machine m;
  std::string trace;
  EXPECT_EQ(mbrt_tracing(m.ctx()), 0);
  mbrt_set_trace_sink(
      m.ctx(),
      [](void* user, const char* data, size_t size) {
        static_cast<std::string*>(user)->append(data, size);
      },
      &trace);
  EXPECT_EQ(mbrt_tracing(m.ctx()), 1);
  mbrt_begin_block(m.ctx(), "p.nc", 4);
  mbrt_trace(m.ctx(), "#1 = 2.000");
  EXPECT_EQ(trace, "p.nc:4: #1 = 2.000\n");
}

TEST(RuntimeAlarm, FinishRecordsMainM99) {
  Machine m;
  mbrt_finish(m.ctx(), MBRT_END_MAIN_M99);
  mbrt_stats stats{};
  mbrt_get_stats(m.ctx(), &stats);
  EXPECT_EQ(stats.main_m99, 1);
}

} // namespace
} // namespace mbc::test
