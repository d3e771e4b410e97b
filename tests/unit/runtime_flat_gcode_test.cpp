// The flattened program (runtime/src/output/flat_gcode.cpp): how words print,
// which words calls take away, and the G10 blocks of offset writes.
#include "runtime_test_support.h"

namespace mbc::test {

namespace {

/// A machine whose flattened program is collected in `text`.
struct Flat {
  explicit Flat(const char* profile = nullptr) : m(profile) {
    mbrt_set_gcode_sink(m.ctx(), &append, &text);
  }

  static void append(void* user, const char* data, size_t size) {
    static_cast<std::string*>(user)->append(data, size);
  }

  Machine m;
  std::string text;
};

} // namespace

TEST(RuntimeFlatGcode, WordsReadBackTheSame) {
  Flat f;
  ASSERT_EQ(f.m.block("G01 X10 Y=1.23456 Z=5 F=33.25"), 0);
  ASSERT_EQ(f.m.block("G54.1 P2 G00 X2.0005"), 0);
  ASSERT_EQ(f.m.block("G04 X1500"), 0);
  ASSERT_EQ(f.m.block("G51 X0 Y0 P=1.5"), 0);
  // Whole-number addresses as the block used them: M3. would be PS0007.
  ASSERT_EQ(f.m.block("S=1200 M=3.4 T=2.5"), 0);
  EXPECT_EQ(f.text, "G1 X0.01 Y1.235 Z5. F33.25\n"
                    "G54.1 P2 G0 X2.001\n"
                    "G4 X1500\n"
                    "G51 X0 Y0 P1.5\n"
                    "S1200 M3 T3\n");
}

// A value with a fraction where the block reads a whole number was rounded:
// the flattened program writes the number the run used, as a literal with
// a fraction would be PS0007 there.
TEST(RuntimeFlatGcode, NumbersAndCountsAsTheBlockUsedThem) {
  Flat f;
  ASSERT_EQ(f.m.block("G04 P=1500.6"), 0);
  ASSERT_EQ(f.m.block("G10 L=10.4 P=1.6 R5."), 0);
  ASSERT_EQ(f.m.block("G54.1 P=2.6"), 0);
  ASSERT_EQ(f.m.block("G81 X1. Z-1. R1. K=2.5 F100."), 0);
  ASSERT_EQ(f.m.block("G80 G=1.04 X5."), 0);
  ASSERT_EQ(f.m.block("G=54.1 P1"), 0);
  EXPECT_EQ(f.text, "G4 P1501\n"
                    "G10 L10 P2 R5.\n"
                    "G54.1 P3\n"
                    "G81 X1. Z-1. R1. K3 F100.\n"
                    "G80 G1 X5.\n"
                    "G54.1 P1\n");
}

// The flattened program is the control's program again: the main program's
// O number and the N of every block that has one.
TEST(RuntimeFlatGcode, KeepsTheProgramNumberAndSequenceNumbers) {
  Flat f;
  mbrt_start(f.m.ctx(), "O12");
  ASSERT_EQ(f.m.block("N10 G00 X1."), 0);
  ASSERT_EQ(f.m.block("G01 X2. F100."), 0);
  mbrt_start(f.m.ctx(), "MAIN"); // no O number: none written
  ASSERT_EQ(f.m.block("N20 X3."), 0);
  EXPECT_EQ(f.text, "O0012\nN10 G0 X1.\nG1 X2. F100.\nN20 X3.\n");
}

TEST(RuntimeFlatGcode, KIsARepeatCountInACycle) {
  Flat f;
  ASSERT_EQ(f.m.block("G81 X1. Z-1. R1. K2 F100."), 0);
  ASSERT_EQ(f.m.block("G80 G17 G02 X0 Y0 I=-0.5 K0"), 0);
  EXPECT_EQ(f.text,
            "G81 X1. Z-1. R1. K2 F100.\nG80 G17 G2 X0. Y0. I-0.5 K0.\n");
}

TEST(RuntimeFlatGcode, CallsLeaveTheirWordsOut) {
  Flat f(R"({"parameters": {"6071": 6, "6001": 32}})");
  ASSERT_EQ(f.m.block("G00 X1. M98 P1000 L2"), 0);
  ASSERT_EQ(f.m.block("M99 P10"), 0);
  ASSERT_EQ(f.m.block("T5 M06"), status(AlarmId::Unsupported)); // two calls
  Flat one(R"({"parameters": {"6071": 6}})");
  ASSERT_EQ(one.m.block("T5 M06"), 0);
  ASSERT_EQ(one.m.block("G67 X2."), 0);
  EXPECT_EQ(f.text, "G0 X1.\nT5 M6\n");
  EXPECT_EQ(one.text, "T5\nX2.\n");
}

TEST(RuntimeFlatGcode, OffsetWritesBecomeG10) {
  Flat f;
  ASSERT_EQ(f.m.block("G91"), 0);
  ASSERT_EQ(f.m.write(5221, -250.1234), 0);
  ASSERT_EQ(f.m.write(7021, 1.5), 0);
  ASSERT_EQ(f.m.write(11003, 120.00049), 0);
  ASSERT_EQ(f.m.write(13001, 5.), 0);
  EXPECT_EQ(f.text, "G91\n"
                    "G90 G10 L2 P1 X-250.123 Y0. Z0.\nG91\n"
                    "G90 G10 L20 P2 X1.5 Y0. Z0.\nG91\n"
                    "G90 G10 L10 P3 R120.\nG91\n"
                    "G90 G10 L12 P1 R5.\nG91\n");
  EXPECT_EQ(f.m.read(11003), 120.0); // offset memory holds increments
}

} // namespace mbc::test
