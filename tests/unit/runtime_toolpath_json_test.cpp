// The toolpath JSON line format: key order, number formatting, escaping and
// independence from the C locale.
#include <mbc/toolpath_json.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdint>
#include <string>

namespace mbc {
namespace {

mbrt_motion linearMotion() {
  mbrt_motion m{};
  m.kind = MBRT_MOTION_LINEAR;
  m.axis_count = 3;
  m.axis_names = "XYZ";
  m.end[0] = 10.0;
  m.end[1] = -1.25;
  m.end[2] = 0.0;
  m.machine[0] = -290.0;
  m.machine[1] = -201.25;
  m.machine[2] = 150.5;
  m.feed = 200.0;
  m.plane = 17;
  m.center_axes[0] = 'X';
  m.center_axes[1] = 'Y';
  m.decimals = 3;
  m.file = "a.nc";
  m.line = 7;
  m.program = "O1000";
  return m;
}

TEST(ToolpathJson, LinearExample) {
  EXPECT_EQ(
      toolpathJsonLine(linearMotion()),
      "{\"motion\":\"linear\",\"x\":10,\"y\":-1.25,\"z\":0,\"mx\":-290,"
      "\"my\":-201.25,\"mz\":150.5,\"f\":200,\"line\":7,\"prog\":\"O1000\"}\n");
}

TEST(ToolpathJson, RapidHasNoFeed) {
  mbrt_motion m = linearMotion();
  m.kind = MBRT_MOTION_RAPID;
  EXPECT_EQ(toolpathJsonLine(m),
            "{\"motion\":\"rapid\",\"x\":10,\"y\":-1.25,\"z\":0,\"mx\":-290,"
            "\"my\":-201.25,\"mz\":150.5,\"line\":7,\"prog\":\"O1000\"}\n");
}

TEST(ToolpathJson, ArcCentreKeysFollowThePlane) {
  mbrt_motion m = linearMotion();
  m.kind = MBRT_MOTION_CW;
  m.plane = 18;
  m.center_axes[0] = 'Z';
  m.center_axes[1] = 'X';
  m.center[0] = 2.5;
  m.center[1] = -0.0001; // rounds to -0.000: printed as 0
  EXPECT_EQ(toolpathJsonLine(m),
            "{\"motion\":\"cw\",\"x\":10,\"y\":-1.25,\"z\":0,\"mx\":-290,"
            "\"my\":-201.25,\"mz\":150.5,\"f\":200,\"cz\":2.5,\"cx\":0,"
            "\"line\":7,\"prog\":"
            "\"O1000\"}\n");
  m.kind = MBRT_MOTION_CCW;
  EXPECT_EQ(toolpathJsonLine(m).substr(0, 18), "{\"motion\":\"ccw\",\"x");
}

TEST(ToolpathJson, NumbersAreTrimmed) {
  mbrt_motion m = linearMotion();
  m.end[0] = -0.0;
  m.end[1] = 1.23456789; // 4 decimals: 1.2346
  m.end[2] = 100.0;
  m.decimals = 4;
  m.feed = 0.012;
  EXPECT_EQ(toolpathJsonLine(m),
            "{\"motion\":\"linear\",\"x\":0,\"y\":1.2346,\"z\":100,\"mx\":-290,"
            "\"my\":-201.25,\"mz\":150.5,\"f\":0.012,\"line\":7,\"prog\":"
            "\"O1000\"}\n");
}

TEST(ToolpathJson, ProgramNamesAreEscaped) {
  mbrt_motion m = linearMotion();
  m.axis_count = 1;
  m.program = "<A\"B\\>";
  EXPECT_EQ(toolpathJsonLine(m),
            "{\"motion\":\"linear\",\"x\":10,\"mx\":-290,\"f\":200,\"line\":7,"
            "\"prog\":\"<A\\\"B\\\\>\"}\n");
}

TEST(ToolpathJson, IgnoresTheCLocale) {
  const std::string saved = std::setlocale(LC_ALL, nullptr);
  if (std::setlocale(LC_ALL, "de_DE.UTF-8") == nullptr &&
      std::setlocale(LC_ALL, "fr_FR.UTF-8") == nullptr) {
    FAIL() << "no locale with a decimal comma installed (make test "
              "installs locales-all)";
  }
  const std::string line = toolpathJsonLine(linearMotion());
  std::setlocale(LC_ALL, saved.c_str());
  EXPECT_EQ(
      line,
      "{\"motion\":\"linear\",\"x\":10,\"y\":-1.25,\"z\":0,\"mx\":-290,"
      "\"my\":-201.25,\"mz\":150.5,\"f\":200,\"line\":7,\"prog\":\"O1000\"}\n");
}

TEST(ToolpathJson, FeedsAreTheShortestText) {
  mbrt_motion m = linearMotion();
  for (const double feed : {0.0, -0.0, 600.0, 1500.5, 0.1, 1e15, 1e16,
                            123456789012345.0, 1.0 / 3.0}) {
    m.feed = feed;
    const std::string line = toolpathJsonLine(m);
    EXPECT_NE(line.find(fmt::format(",\"f\":{},", feed)), std::string::npos)
        << line;
  }
}

// The writer thread counts toolpathJsonBound against the output limit in
// place of the record's bytes: it must never be less, whatever the numbers
// (increments, values past any count, NaN), the axes, the arc, the cycle
// and the program's name (escapes make a character six).
TEST(ToolpathJson, TheBoundIsNeverBelowTheRecord) {
  std::uint32_t state = 11;
  const auto next = [&state](std::uint32_t below) {
    state = state * 1103515245u + 12345u;
    return (state >> 16) % below;
  };
  const double extremes[] = {0.0,    -0.0,    1e15,     -1e15, 1.0e300,
                             -1e308, 1.0 / 3, 123.4565, 5e-324};
  for (int round = 0; round < 2000; ++round) {
    mbrt_motion m = linearMotion();
    m.kind = static_cast<int>(next(4));
    m.axis_count = static_cast<int>(1 + next(MBRT_MAX_AXES));
    m.axis_names = "XYZABCUVW";
    m.decimals = static_cast<int>(next(10));
    const auto number = [&] {
      return next(4) == 0 ? extremes[next(std::size(extremes))]
                          : (static_cast<double>(next(2000000)) - 1e6) /
                                std::pow(10.0, next(6));
    };
    for (int axis = 0; axis < m.axis_count; ++axis) {
      m.end[axis] = number();
      m.machine[axis] = number();
    }
    m.center[0] = number();
    m.center[1] = number();
    m.feed = number();
    m.cycle = next(2) == 0 ? 0 : static_cast<int>(next(100000));
    m.line = static_cast<int>(next(2000000000));
    std::string name(next(40), 'A');
    for (char& c : name) {
      c = static_cast<char>(1 + next(126));
    }
    m.program = name.c_str();
    EXPECT_GE(toolpathJsonBound(m), toolpathJsonLine(m).size())
        << toolpathJsonLine(m);
  }
}

} // namespace
} // namespace mbc
