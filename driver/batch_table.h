// The parameter table of `mbc batch`: a CSV file whose header names the
// columns (a G65 argument letter, a variable `#N` to preset, or `id`) and
// whose every further line is one run of the main program.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mbc::driver {

struct BatchRow {
  std::string id; // the id column, or the row's number, zero-padded
  int line = 0;   // in the table file
  std::vector<std::pair<double, double>> presets; // #N columns
  std::vector<std::pair<char, double>> args;      // letter columns
};

/// `--column NAME=TARGET`: the table's column NAME is the argument letter,
/// `#N` or `id` TARGET; an empty TARGET ignores the column.
using ColumnMap = std::vector<std::pair<std::string, std::string>>;

/// Reads the table. An empty cell passes nothing (the argument or variable
/// stays vacant). False with "PATH:LINE:COLUMN: reason" in `error`.
bool readBatchTable(const std::string& path, const ColumnMap& columnMap,
                    std::vector<BatchRow>& rows, std::string& error);

/// "I/N" (0 <= I < N): the rows whose 0-based position P has P % N == I.
struct Shard {
  int index = 0;
  int count = 1;
};

bool parseShard(const std::string& text, Shard& shard);

} // namespace mbc::driver
