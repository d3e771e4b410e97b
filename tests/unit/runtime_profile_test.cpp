// Machine profiles through mbrt_create: the built-in default, every field,
// and errors that name the offending key.
#include <mbc/calling_codes.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

TEST(RuntimeProfile, DefaultIsAThreeAxisMetricMill) {
  Machine m;
  ASSERT_EQ(m.block("G00 X1. Y2. Z3."), 0);
  EXPECT_EQ(m.motions()[0].axis_count, 3);
  EXPECT_STREQ(m.motions()[0].axis_names, "XYZ");
  EXPECT_EQ(m.motions()[0].decimals, 3);
  EXPECT_EQ(m.read(4006), 21.0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 3410), 0.02);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 3401), 0.0);
  EXPECT_EQ(mbrt_block_skip(m.ctx()), 0);
}

TEST(RuntimeProfile, EveryField) {
  Machine m(R"({
    "axes": ["X", "Y", "Z", "B"],
    "units": "inch",
    "rapid_rate": 5000,
    "parameters": {"3401": 0, "6001": 2, "6004": 1, "3410": 0.05},
    "tool_offsets": {"count": 99, "1": {"h_geometry": 4.5}},
    "work_offsets": {"EXT": [0, 0, 0, 0], "G54": [1, 2, 3, 4],
                     "G54.1P300": [9]},
    "variables": {"500": 1.5},
    "extended_common": true,
    "limits": {"macro_nesting": 4, "subprogram_nesting": 8,
               "total_nesting": 12},
    "parts": {"count": 3, "required": 7},
    "block_skip": true
  })");
  EXPECT_EQ(m.read(4006), 20.0);
  EXPECT_EQ(m.read(5224), 4.0);
  EXPECT_EQ(m.read(19981), 9.0);
  EXPECT_EQ(m.read(11001), 4.5);
  EXPECT_EQ(m.read(500), 1.5);
  EXPECT_TRUE(isVacant(m.read(300)));
  EXPECT_EQ(m.read(3901), 3.0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 6004), 1.0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 6001), 2.0);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 3410), 0.05);
  EXPECT_EQ(mbrt_parameter(m.ctx(), 1234), 0.0);
  EXPECT_EQ(mbrt_block_skip(m.ctx()), 1);
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(m.ctx(), 10100, &value),
            status(AlarmId::VariableOutOfRange));
  // 1 inch of rapid at 5000 mm/min.
  ASSERT_EQ(m.block("G91 G00 X1."), 0);
  EXPECT_EQ(m.read(3001), std::floor(25.4 / 5000.0 * 60000.0));
  for (int level = 1; level <= 4; ++level) {
    ASSERT_EQ(m.callMacro("O9000", ""), 0);
  }
  EXPECT_EQ(m.callMacro("O9000", ""), status(AlarmId::TooManyMacroNesting));
}

TEST(RuntimeProfile, ErrorsNameTheKey) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"axis": ["X"]})", "\"axis\""},
      {R"({"axes": ["X", "X"]})", "\"axes\""},
      {R"({"axes": ["Q"]})", "\"axes\""},
      {R"({"axes": []})", "\"axes\""},
      {R"({"axes": "XYZ"})", "\"axes\""},
      {R"({"units": "furlong"})", "\"units\""},
      {R"({"rapid_rate": "fast"})", "\"rapid_rate\""},
      {R"({"rapid_rate": 0})", "\"rapid_rate\""},
      {R"({"parameters": {"1234": 1}})", "\"parameters.1234\""},
      {R"({"parameters": {"3401": 1.5}})", "\"parameters.3401\""},
      {R"({"parameters": {"3410": -1}})", "\"parameters.3410\""},
      {R"({"parameters": {"1241": 5}})", "\"parameters.1241\""},
      {R"({"parameters": {"1241": [1, 2, 3, 4]}})", "\"parameters.1241\""},
      {R"({"parameters": {"1242": [0, "1"]}})", "\"parameters.1242[1]\""},
      {R"({"tool_offsets": {"count": 10, "11": {}}})", "\"tool_offsets.11\""},
      {R"({"tool_offsets": {"1": {"h_geom": 1}}})",
       "\"tool_offsets.1.h_geom\""},
      {R"({"tool_offsets": {"count": 0}})", "\"tool_offsets.count\""},
      {R"({"work_offsets": {"G60": [1]}})", "\"work_offsets.G60\""},
      {R"({"work_offsets": {"G54.1P301": [1]}})", "\"work_offsets.G54.1P301\""},
      {R"({"work_offsets": {"G54": [1, 2, 3, 4]}})", "\"work_offsets.G54\""},
      {R"({"work_offsets": {"G54": [1, "2"]}})", "\"work_offsets.G54\""},
      {R"({"work_offsets": {"G55": [1e20]}})", "\"work_offsets.G55\""},
      {R"({"variables": {"100": 1}})", "\"variables.100\""},
      {R"({"variables": {"500": "x"}})", "\"variables.500\""},
      {R"({"extended_common": 1})", "\"extended_common\""},
      {R"({"limits": {"macro_nesting": "5"}})", "\"limits.macro_nesting\""},
      {R"({"limits": {"depth": 5}})", "\"limits.depth\""},
      {R"({"parts": {"made": 5}})", "\"parts.made\""},
      {R"({"block_skip": "yes"})", "\"block_skip\""},
      {R"({"program_number_digits": 5})", "\"program_number_digits\""},
      {R"({"input_signals": {"1036": 1}})", "\"input_signals.1036\""},
      {R"({"tool_offsets": {"memory": "D"}})", "\"tool_offsets.memory\""},
      {R"({"tool_offsets": {"memory": "A", "1": {"h_wear": 1}}})",
       "\"tool_offsets.1.h_wear\""},
      {R"({"tool_offsets": {"memory": "B", "1": {"d_wear": 1}}})",
       "\"tool_offsets.1.d_wear\""},
      {R"({"input_signals": {"1001": 2}})", "\"input_signals.1001\""},
      {R"({"input_signals": {"1032": 4294967296}})", "\"input_signals.1032\""},
      {R"({"probe": []})", "\"probe\""},
      {R"({"probe": {"tip": 1}})", "\"probe.tip\""},
      {R"({"probe": {"radius": -1}})", "\"probe.radius\""},
      {R"({"probe": {"scene": {}}})", "\"probe.scene\""},
      {R"({"probe": {"scene": [{"type": "cone"}]}})",
       "\"probe.scene[0].type\""},
      {R"({"probe": {"scene": [{"type": "box", "min": [0, 0, 0],
           "max": [1, 1, 0]}]}})",
       "\"probe.scene[0]\""},
      {R"({"probe": {"scene": [{"type": "box", "radius": 1}]}})",
       "\"probe.scene[0].radius\""},
      {R"({"probe": {"scene": [{"type": "sphere", "center": [0, 0]}]}})",
       "\"probe.scene[0].center\""},
      {R"({"probe": {"scene": [{"type": "sphere", "center": [0, 0, 0]}]}})",
       "\"probe.scene[0].radius\""},
      {R"({"probe": {"scene": [{"type": "bore", "center": [0, 0],
           "radius": 5, "z": [0, -1]}]}})",
       "\"probe.scene[0].z\""},
      {R"({"probe": {"scene": [{"type": "plane", "point": [0, 0, 0],
           "normal": [0, 0, 0]}]}})",
       "\"probe.scene[0].normal\""},
  };
  for (const auto& [json, key] : cases) {
    const std::string error = profileError(json);
    EXPECT_NE(error.find(key), std::string::npos) << json << " gave: " << error;
    EXPECT_EQ(error.rfind("machine profile: ", 0), 0u) << error;
  }
}

// The calling-code parameters follow the one rule the IR passes assume
// (<mbc/calling_codes.h>): no FANUC G code, and no M code that stops,
// ends, calls or returns, can be made to call; 0 means no code.
TEST(RuntimeProfile, CallingCodesFollowTheCompilersRule) {
  for (const char* bad :
       {R"({"parameters": {"6050": 1}})", R"({"parameters": {"6059": -66}})",
        R"({"parameters": {"6071": 30}})", R"({"parameters": {"6079": 0.5}})",
        R"({"parameters": {"6080": 98}})", R"({"parameters": {"6089": 2}})"}) {
    EXPECT_NE(profileError(bad), "") << bad;
  }
  for (const char* good :
       {R"({"parameters": {"6050": 100, "6051": -110, "6052": 0}})",
        R"({"parameters": {"6071": 6, "6080": 50, "6081": 0}})"}) {
    EXPECT_EQ(profileError(good), "") << good;
  }
  EXPECT_FALSE(mayBeCustomGCode(650));
  EXPECT_TRUE(mayBeCustomGCode(1000));
  EXPECT_TRUE(gCodeMayCall(661, true));
  EXPECT_FALSE(gCodeMayCall(661, false));
  for (double m : {0.0, 1.0, 2.0, 30.0}) {
    EXPECT_FALSE(mCodeMayCall(m)) << m;
    EXPECT_FALSE(mayBeCustomMCode(m)) << m;
  }
  EXPECT_TRUE(mCodeMayCall(98));
  EXPECT_FALSE(mayBeCustomMCode(98));
  EXPECT_TRUE(mayBeCustomMCode(6));
}

TEST(RuntimeProfile, InvalidJson) {
  EXPECT_NE(profileError("{\"axes\": [").find("invalid JSON"),
            std::string::npos);
  EXPECT_NE(profileError("[1, 2]").find("top level"), std::string::npos);
}

TEST(RuntimeProfile, ErrorBufferIsNeverOverrun) {
  char err[10];
  std::memset(err, 'x', sizeof err);
  EXPECT_EQ(mbrt_create(R"({"nope": 1})", err, 6), nullptr);
  EXPECT_EQ(std::string(err), "machi");
  EXPECT_EQ(err[6], 'x');
  EXPECT_EQ(mbrt_create(R"({"nope": 1})", nullptr, 0), nullptr);
}

TEST(RuntimeProfile, FromFile) {
  const std::string path =
      ::testing::TempDir() + "runtime_profile_test_profile.json";
  {
    std::ofstream out(path);
    out << R"({"axes": ["X", "Z"]})";
  }
  char err[256] = "";
  mbrt_ctx* ctx = mbrt_create_from_file(path.c_str(), err, sizeof err);
  ASSERT_NE(ctx, nullptr) << err;
  mbrt_num value = 0;
  EXPECT_EQ(mbrt_read_var(ctx, 5003, &value), 0);
  mbrt_destroy(ctx);
  std::remove(path.c_str());
  EXPECT_EQ(mbrt_create_from_file("/nonexistent/profile.json", err, sizeof err),
            nullptr);
  EXPECT_NE(std::string(err).find("/nonexistent/profile.json"),
            std::string::npos);
}

} // namespace
} // namespace mbc::test
