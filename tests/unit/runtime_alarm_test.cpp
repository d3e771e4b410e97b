// Alarms and their report: location, message, detail, the call stack, the
// first alarm winning, snprintf-style truncation; the run's statistics.
#include <fmt/format.h>

#include <string>
#include <utility>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

using namespace std::string_literals;

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
  // The same, piece by piece.
  char message[64];
  EXPECT_EQ(mbrt_alarm_message(m.ctx(), message, sizeof message), 11U);
  EXPECT_STREQ(message, "ZERO DIVIDE");
  EXPECT_STREQ(mbrt_alarm_file(m.ctx()), "sub.nc");
  EXPECT_EQ(mbrt_alarm_line(m.ctx()), 50);
  ASSERT_EQ(mbrt_alarm_depth(m.ctx()), 2U);
  std::string calls;
  const char* program = nullptr;
  const char* file = nullptr;
  int line = 0;
  for (size_t level = 0;
       mbrt_alarm_call(m.ctx(), level, &program, &file, &line) != 0; ++level) {
    calls += fmt::format("{} {}:{};", program, file, line);
  }
  EXPECT_EQ(calls, "O9200 main.nc:43;O9100 main.nc:5;");
}

TEST(RuntimeAlarm, NoPartsWithoutAnAlarm) {
  Machine m;
  char message[8] = "x";
  EXPECT_EQ(mbrt_alarm_message(m.ctx(), message, sizeof message), 0U);
  EXPECT_STREQ(message, "");
  EXPECT_STREQ(mbrt_alarm_file(m.ctx()), "");
  EXPECT_EQ(mbrt_alarm_line(m.ctx()), 0);
  EXPECT_EQ(mbrt_alarm_depth(m.ctx()), 0U);
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

/// The control's number and code of the pending alarm, and the C names of
/// the statuses.
std::pair<int, std::string> numberAndCode(mbrt_ctx* ctx) {
  std::string code(mbrt_alarm_code(ctx, nullptr, 0), '\0');
  mbrt_alarm_code(ctx, code.data(), code.size() + 1);
  return {mbrt_alarm_number(ctx), code};
}

TEST(RuntimeAlarm, NumberAndCodeAsTheControlShowsThem) {
  Machine none;
  EXPECT_EQ(numberAndCode(none.ctx()), std::make_pair(0, std::string()));

  Machine program;
  mbrt_begin_block(program.ctx(), "p.nc", 3);
  EXPECT_EQ(mbrt_raise(program.ctx(), MBRT_ALARM_ZeroDivide, nullptr),
            status(AlarmId::ZeroDivide));
  EXPECT_EQ(numberAndCode(program.ctx()), std::make_pair(112, "PS0112"s));
  char small[4];
  EXPECT_EQ(mbrt_alarm_code(program.ctx(), small, sizeof small), 6U);
  EXPECT_STREQ(small, "PS0");

  Machine macro; // #3000 = 1 (X IS MISSING)
  EXPECT_EQ(macro.write(3000, 1.0, "X IS MISSING"), MBRT_ALARM_MacroAlarm);
  EXPECT_EQ(numberAndCode(macro.ctx()), std::make_pair(3001, "3001"s));

  Machine ours;
  mbrt_raise(ours.ctx(), MBRT_ALARM_ExecutionLimit, nullptr);
  EXPECT_EQ(numberAndCode(ours.ctx()), std::make_pair(2, "MBC0002"s));
}

TEST(RuntimeAlarm, TheCNamesAreTheIds) {
  EXPECT_EQ(MBRT_OK, 0);
  EXPECT_EQ(MBRT_ALARM_None, status(AlarmId::None));
  EXPECT_EQ(MBRT_ALARM_TooManyDigits, status(AlarmId::TooManyDigits));
  EXPECT_EQ(MBRT_ALARM_InterferenceInCircle,
            status(AlarmId::InterferenceInCircle));
}

TEST(RuntimeVersion, TheLibraryIsTheHeaders) {
  EXPECT_STREQ(mbrt_version(), MBC_VERSION_STRING);
  EXPECT_EQ(MBC_VERSION, MBC_VERSION_MAJOR * 10000 + MBC_VERSION_MINOR * 100 +
                             MBC_VERSION_PATCH);
  EXPECT_EQ(std::string(mbrt_version()),
            fmt::format("{}.{}.{}", MBC_VERSION_MAJOR, MBC_VERSION_MINOR,
                        MBC_VERSION_PATCH));
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
