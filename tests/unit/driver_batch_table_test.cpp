// The parameter table of mbc batch: CSV as spreadsheets write it, the
// column kinds, row ids, and errors with line and column.
#include "driver/batch_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace mbc::driver {
namespace {

class BatchTableTest : public ::testing::Test {
protected:
  // Reads `text` as a table file; the error (if any) in error_.
  bool read(const std::string& text, const ColumnMap& columns = {}) {
    {
      std::ofstream out(path_, std::ios::binary);
      out << text;
    }
    rows_.clear();
    error_.clear();
    return readBatchTable(path_, columns, rows_, error_);
  }

  void TearDown() override { std::remove(path_.c_str()); }

  // One file per test: ctest runs the tests of this fixture in parallel.
  std::string path_ =
      ::testing::TempDir() + "batch_table_test_" +
      ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv";
  std::vector<BatchRow> rows_;
  std::string error_;
};

TEST_F(BatchTableTest, ArgumentsPresetsAndNumberedIds) {
  ASSERT_TRUE(read("R,h,#500,Z\r\n10,4,7,-2.5\r\n\r\n1.5,,,\r\n")) << error_;
  ASSERT_EQ(rows_.size(), 2u);
  EXPECT_EQ(rows_[0].id, "1");
  EXPECT_EQ(rows_[0].line, 2);
  EXPECT_EQ(rows_[0].args, (std::vector<std::pair<char, double>>{
                               {'R', 10}, {'H', 4}, {'Z', -2.5}}));
  EXPECT_EQ(rows_[0].presets,
            (std::vector<std::pair<double, double>>{{500, 7}}));
  // Empty cells pass nothing; the blank line is skipped.
  EXPECT_EQ(rows_[1].line, 4);
  EXPECT_EQ(rows_[1].args, (std::vector<std::pair<char, double>>{{'R', 1.5}}));
  EXPECT_TRUE(rows_[1].presets.empty());
}

TEST_F(BatchTableTest, ByteOrderMarkOfExcelsCsvUtf8) {
  ASSERT_TRUE(read("\xEF\xBB\xBFR,H\r\n10,4\r\n")) << error_;
  ASSERT_EQ(rows_.size(), 1u);
  EXPECT_EQ(rows_[0].args,
            (std::vector<std::pair<char, double>>{{'R', 10}, {'H', 4}}));
}

TEST_F(BatchTableTest, SemicolonsAndDecimalCommas) {
  ASSERT_TRUE(read("id;R;#500\np1;12,5;-0,25\np2;\"3,5\";1.5\n")) << error_;
  ASSERT_EQ(rows_.size(), 2u);
  EXPECT_EQ(rows_[0].args, (std::vector<std::pair<char, double>>{{'R', 12.5}}));
  EXPECT_EQ(rows_[0].presets,
            (std::vector<std::pair<double, double>>{{500, -0.25}}));
  EXPECT_EQ(rows_[1].args, (std::vector<std::pair<char, double>>{{'R', 3.5}}));
  EXPECT_EQ(rows_[1].presets,
            (std::vector<std::pair<double, double>>{{500, 1.5}}));
  // A comma table keeps its decimal points: "1,5" is two cells there.
  EXPECT_FALSE(read("R,H\n1,5\n1\n"));
}

TEST_F(BatchTableTest, ColumnsMappedAndIgnored) {
  ASSERT_TRUE(read("Part,Depth,note,R\nA-1,-4,\"left; check\",5\n",
                   {{"part", "id"}, {"DEPTH", "Z"}, {"note", ""}}))
      << error_;
  ASSERT_EQ(rows_.size(), 1u);
  EXPECT_EQ(rows_[0].id, "A-1");
  EXPECT_EQ(rows_[0].args,
            (std::vector<std::pair<char, double>>{{'Z', -4}, {'R', 5}}));
  EXPECT_FALSE(read("depth,R\n1,2\n"));
  EXPECT_NE(error_.find(":1:1: unknown column 'depth'"), std::string::npos)
      << error_;
  EXPECT_NE(error_.find("--column 'depth=R' maps it"), std::string::npos);
  EXPECT_FALSE(read("depth,R\n1,2\n", {{"depth", "Z"}, {"width", "W"}}));
  EXPECT_NE(error_.find("--column width: the header has no column 'width'"),
            std::string::npos)
      << error_;
  EXPECT_FALSE(read("depth,Z\n1,2\n", {{"depth", "Z"}}));
  EXPECT_NE(error_.find("column 'Z' appears twice"), std::string::npos)
      << error_;
}

// Every column the header cannot have is named at once, each at its place,
// a line each: a table from elsewhere is fixed in one round.
TEST_F(BatchTableTest, EveryUnknownColumnIsReported) {
  EXPECT_FALSE(read("id,depth,R,speed,L,R\n1,2,3,4,5,6\n", {{"width", "W"}}));
  const std::string expected[] = {
      ":1:4: unknown column 'depth'", ":1:12: unknown column 'speed'",
      ":1:18: 'L' is not a G65 argument", ":1:20: column 'R' appears twice",
      ":1:1: --column width: the header has no column 'width'"};
  for (const std::string& line : expected) {
    EXPECT_NE(error_.find(line), std::string::npos) << line << "\n" << error_;
  }
  EXPECT_EQ(std::count(error_.begin(), error_.end(), '\n'), 4) << error_;
}

TEST_F(BatchTableTest, NumberedIdsArePaddedToTheLargest) {
  std::string text = "R\n";
  for (int i = 0; i < 12; ++i) {
    text += "1\n";
  }
  ASSERT_TRUE(read(text)) << error_;
  EXPECT_EQ(rows_.front().id, "01");
  EXPECT_EQ(rows_.back().id, "12");
}

TEST_F(BatchTableTest, QuotedCellsAndTheIdColumn) {
  ASSERT_TRUE(read("id, X ,\"Y\"\n\"part-1\", 2 ,\"3\"\npart.2,\"\",4\n"))
      << error_;
  ASSERT_EQ(rows_.size(), 2u);
  EXPECT_EQ(rows_[0].id, "part-1");
  EXPECT_EQ(rows_[0].args,
            (std::vector<std::pair<char, double>>{{'X', 2}, {'Y', 3}}));
  EXPECT_EQ(rows_[1].id, "part.2");
  EXPECT_EQ(rows_[1].args, (std::vector<std::pair<char, double>>{{'Y', 4}}));
}

TEST_F(BatchTableTest, ErrorsSayWhere) {
  const std::pair<const char*, std::string> cases[] = {
      {"R,L\n", ":1:3: 'L' is not a G65 argument (G, L, N, O and P are not); "
                "use its variable #N instead"},
      {"R,speed\n", ":1:3: unknown column 'speed' (a G65 argument letter "
                    "such as R, a variable such as #100, or id; --column "
                    "'speed=R' maps it, --column 'speed=' ignores it)"},
      {"R,r\n", ":1:3: column 'r' appears twice"},
      {"#0\n", ":1:1: unknown column '#0' (a G65 argument letter such as R, "
               "a variable such as #100, or id; --column '#0=R' maps it, "
               "--column '#0=' ignores it)"},
      {"R,H\n1,2\n1,2e\n", ":3:3: '2e' is not a number"},
      {"R,H\n1\n", ":2:1: 1 cells, but the header names 2 columns"},
      {"id,R\nx,1\n\"x\",2\n", ":3:1: id 'x' is used twice"},
      {"id,R\n.hidden,1\n", ":2:1: id '.hidden' is not usable in file names "
                            "(letters, digits, '-', '_' and '.')"},
      {"R,H\n1,\"2\n", ":2:3: unterminated quoted cell"},
      {"\n\n", ": no header line naming the columns"}};
  for (const auto& [text, error] : cases) {
    EXPECT_FALSE(read(text)) << text;
    EXPECT_EQ(error_, path_ + error) << text;
  }
}

TEST(BatchShard, IndexOfCount) {
  Shard s;
  ASSERT_TRUE(parseShard("2/5", s));
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 5);
  EXPECT_TRUE(parseShard("0/1", s));
  for (const char* bad : {"5/5", "-1/3", "1/0", "1", "1/2x", "/2", "a/b"}) {
    EXPECT_FALSE(parseShard(bad, s)) << bad;
  }
}

} // namespace
} // namespace mbc::driver
