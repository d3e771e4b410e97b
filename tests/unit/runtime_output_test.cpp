// DPRNT, BPRNT, POPEN and PCLOS through the C ABI and the print sink.
#include "runtime_test_support.h"

namespace mbc::test {
namespace {

mbrt_print_item text(const char* t) {
  return {t, 0.0, 0, 0};
}

mbrt_print_item value(double v, int c, int d) {
  return {nullptr, v, c, d};
}

TEST(RuntimeOutput, DprntThroughTheSink) {
  Machine m;
  const mbrt_print_item items[] = {text("X"), value(128.47398, 5, 3),
                                   text("Y"), value(-91.2, 5, 3),
                                   text("T"), value(123.456, 2, 0)};
  EXPECT_EQ(mbrt_dprnt(m.ctx(), items, 6), 0);
  EXPECT_EQ(m.printed(), "X   128.474Y-   91.200T 23\n");
}

TEST(RuntimeOutput, DprntWithPrtFromTheProfile) {
  Machine m(R"({"parameters": {"6001": 2}})");
  const mbrt_print_item items[] = {text("X"), value(128.47398, 5, 3),
                                   text("Y"), value(-91.2, 5, 3),
                                   text("T"), value(123.456, 2, 0)};
  EXPECT_EQ(mbrt_dprnt(m.ctx(), items, 6), 0);
  EXPECT_EQ(m.printed(), "X128.474Y-91.200T23\n");
}

TEST(RuntimeOutput, DprntTextStarIsASpaceAndVacantIsZero) {
  Machine m;
  const mbrt_print_item items[] = {text("DIA*"), value(vacant(), 1, 1)};
  EXPECT_EQ(mbrt_dprnt(m.ctx(), items, 2), 0);
  EXPECT_EQ(mbrt_dprnt(m.ctx(), nullptr, 0), 0);
  EXPECT_EQ(m.printed(), "DIA  0.0\n\n");
}

TEST(RuntimeOutput, WithoutASinkOutputIsDiscarded) {
  char err[128];
  mbrt_ctx* ctx = mbrt_create(nullptr, err, sizeof err);
  ASSERT_NE(ctx, nullptr);
  const mbrt_print_item items[] = {text("A"), value(1.0, 1, 0)};
  EXPECT_EQ(mbrt_dprnt(ctx, items, 2), 0);
  EXPECT_EQ(mbrt_bprnt(ctx, items, 2), 0);
  mbrt_destroy(ctx);
}

TEST(RuntimeOutput, BprntBytes) {
  Machine m;
  const mbrt_print_item items[] = {text("A"), value(0.25, 0, 3),
                                   text("B"), value(-3.5, 0, 2),
                                   text("C"), value(12.34, 0, 0)};
  EXPECT_EQ(mbrt_bprnt(m.ctx(), items, 6), 0);
  const std::string expected("A\x00\x00\x00\xFA"
                             "B\xFF\xFF\xFE\xA2"
                             "C\x00\x00\x00\x0C\n",
                             16);
  EXPECT_EQ(m.printed(), expected);
}

TEST(RuntimeOutput, BprntValueThatDoesNotFit) {
  Machine m;
  const mbrt_print_item items[] = {value(3e9, 0, 0)};
  EXPECT_EQ(mbrt_bprnt(m.ctx(), items, 1), status(AlarmId::ArgumentOutOfRange));
  EXPECT_EQ(m.printed(), "");
}

TEST(RuntimeOutput, PopenAndPclosWriteNothing) {
  Machine m;
  EXPECT_EQ(mbrt_popen(m.ctx()), 0);
  EXPECT_EQ(mbrt_pclos(m.ctx()), 0);
  EXPECT_EQ(m.printed(), "");
}

TEST(RuntimeOutputLimit, TheBlockAfterTheLimitStopsWithTheWritersLocation) {
  Machine m;
  mbrt_set_max_output(m.ctx(), 10);
  const mbrt_print_item items[] = {text("ABCD")};
  for (int line = 1; line <= 2; ++line) {
    ASSERT_EQ(m.block("", line), 0);
    EXPECT_EQ(mbrt_dprnt(m.ctx(), items, 1), 0);
  }
  ASSERT_EQ(m.block("", 3), 0);
  EXPECT_EQ(mbrt_dprnt(m.ctx(), items, 1), 0); // 15 bytes: past the limit
  EXPECT_EQ(m.block("", 4), status(AlarmId::OutputLimit));
  EXPECT_EQ(m.printed(), "ABCD\nABCD\nABCD\n");
  EXPECT_EQ(m.report(), "test.nc:3: alarm MBC0003: OUTPUT LIMIT REACHED: "
                        "more than 10 bytes written (--max-output)\n");
}

TEST(RuntimeOutputLimit, EachRunStartsWithTheWholeBudgetAndItsBlockLimit) {
  Machine m;
  mbrt_set_max_output(m.ctx(), 4);
  mbrt_set_max_blocks(m.ctx(), 3);
  const mbrt_print_item items[] = {text("ABCD")};
  ASSERT_EQ(m.block(""), 0);
  EXPECT_EQ(mbrt_dprnt(m.ctx(), items, 1), 0);
  EXPECT_EQ(m.block(""), status(AlarmId::OutputLimit));
  mbrt_start(m.ctx(), "O1000");
  for (int line = 1; line <= 3; ++line) {
    ASSERT_EQ(m.block("", line), 0);
  }
  EXPECT_EQ(m.block("", 4), status(AlarmId::ExecutionLimit));
}

TEST(RuntimeOutputLimit, MotionsCountWhatTheSinkReports) {
  Machine m;
  mbrt_set_max_output(m.ctx(), 100);
  mbrt_count_output(m.ctx(), 100);
  ASSERT_EQ(m.block("G00 X1.", 1), 0);
  mbrt_count_output(m.ctx(), 1);
  EXPECT_EQ(m.block("G00 X2.", 2), status(AlarmId::OutputLimit));
  EXPECT_EQ(m.motions().size(), 1U);
}

TEST(RuntimeOutputLimit, BufferedMotionsCountTheirSize) {
  Machine m;
  mbrt_buffer_motions(m.ctx(), 1);
  mbrt_set_max_output(m.ctx(), 2 * sizeof(mbrt_motion));
  ASSERT_EQ(m.block("G00 X1.", 1), 0);
  ASSERT_EQ(m.block("G00 X2.", 2), 0);
  ASSERT_EQ(m.block("G00 X3.", 3), 0);
  EXPECT_EQ(m.block("G00 X4.", 4), status(AlarmId::OutputLimit));
  size_t count = 0;
  mbrt_buffered_motions(m.ctx(), &count);
  EXPECT_EQ(count, 3U);
}

} // namespace
} // namespace mbc::test
