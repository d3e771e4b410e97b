// The G code table (runtime/src/tables/g_codes.def) against what a run does
// with each of its codes, in both series and every lathe G code system:
// a code sets the state its row names, which #4001+ reads back as the code,
// and a code mbc does not execute stops the run with MBC0001.
#include "runtime/src/tables/g_codes.h"
#include <mbc/g_codes.h>

#include <string>

#include "runtime_test_support.h"

namespace mbc::test {
namespace {

using rt::GCodeRow;
using rt::kNo;
using rt::ModalField;

struct Column {
  char name;
  const char* profile;
};

constexpr Column kColumns[] = {
    {'M', nullptr},
    {'A', R"({"series": "T"})"},
    {'B', R"({"series": "T", "parameters": {"3401": 64}})"},
    {'C', R"({"series": "T", "parameters": {"3401": 128}})"},
};

/// The block that selects a row's code: codes whose words are their data
/// get words that make them act.
std::string blockOf(const GCodeRow& row, char column) {
  const std::string code = gCodeText(row.tenths(column));
  switch (row.field) {
    case ModalField::Scaling:
      return row.code == 510 ? code + " X0 Y0 P2." : code;
    case ModalField::Rotation:
      return row.code == 680 ? code + " X0 Y0 R30." : code;
    case ModalField::Mirror:
      return code + " X0";
    case ModalField::Length:
      return code + " H1";
    default:
      return code;
  }
}

TEST(RuntimeGCodeTable, EveryModalCodeReadsBackInItsGroup) {
  int checked = 0;
  for (const Column& column : kColumns) {
    const bool lathe = column.name != 'M';
    for (const GCodeRow& row : rt::gCodeRows()) {
      const int group = rt::modalGroup(row.field, lathe);
      // G66 and G66.1 are calls (block_calls_test).
      if (!row.modelled || row.tenths(column.name) == kNo || group == 0 ||
          row.code == 660 || row.code == 661) {
        continue;
      }
      Machine m(column.profile);
      const std::string block = blockOf(row, column.name);
      ASSERT_EQ(m.block(block), 0) << column.name << ": " << block << "\n"
                                   << m.report();
      EXPECT_EQ(m.read(4000 + group), row.tenths(column.name) / 10.0)
          << column.name << ": " << block << " in group " << group;
      ++checked;
    }
  }
  EXPECT_GT(checked, 150);
}

TEST(RuntimeGCodeTable, EveryCodeOfAColumnRunsOrStopsWithMbc0001) {
  for (const Column& column : kColumns) {
    for (const GCodeRow& row : rt::gCodeRows()) {
      if (row.tenths(column.name) == kNo || row.modelled) {
        continue;
      }
      Machine m(column.profile);
      const std::string block = gCodeText(row.tenths(column.name));
      EXPECT_NE(m.block(block), 0) << column.name << ": " << block;
      EXPECT_NE(m.report().find("MBC0001"), std::string::npos)
          << column.name << ": " << block << "\n"
          << m.report();
      EXPECT_NE(m.report().find(row.name), std::string::npos) << m.report();
    }
  }
}

// A code the column lacks is PS0010 even where another column has it: G90
// of system A is the turning cycle, system B's is G77; G92.1 is G50.3 in
// system A and a mill has no G50.3; G07.5 is no code at all.
TEST(RuntimeGCodeTable, ACodeTheColumnLacksIsImproper) {
  const auto improper = [](const char* profile, const char* block) {
    Machine m(profile);
    return m.block(block) != 0 &&
           m.report().find("PS0010") != std::string::npos;
  };
  EXPECT_TRUE(improper(kColumns[1].profile, "G77"));
  EXPECT_TRUE(improper(kColumns[1].profile, "G92.1"));
  EXPECT_TRUE(improper(kColumns[2].profile, "G50.3"));
  EXPECT_TRUE(improper(kColumns[3].profile, "G50.3"));
  EXPECT_TRUE(improper(nullptr, "G7.5"));
  EXPECT_TRUE(improper(nullptr, "G50.3"));
  EXPECT_FALSE(improper(kColumns[2].profile, "G77"));
  EXPECT_FALSE(improper(kColumns[1].profile, "G50.3 X0 Z0"));
}

// A block holds one code whose words are its data, on a lathe as on a
// mill, and the alarm names the codes as the G code system writes them.
TEST(RuntimeGCodeTable, OneDataCodeInABlock) {
  Machine a(kColumns[1].profile);
  EXPECT_NE(a.block("G50 X100. Z50. G10 P1 X1. Z1."), 0);
  EXPECT_NE(
      a.report().find("PS0010: IMPROPER G-CODE: G50 and G10 in one block"),
      std::string::npos)
      << a.report();
  Machine b(kColumns[2].profile);
  EXPECT_NE(b.block("G92 X100. Z50. G52 X1."), 0);
  EXPECT_NE(b.report().find("G92 and G52 in one block"), std::string::npos)
      << b.report();
}

} // namespace
} // namespace mbc::test
