// CSV as spreadsheets and pandas write it: commas, optional double quotes
// (a quote inside doubled), CRLF or LF line ends, blank lines skipped,
// spaces around a cell ignored; Excel's "CSV UTF-8" byte order mark; and
// the semicolons and decimal commas of the locales whose decimal point is
// a comma.
#include "driver/batch_table.h"

#include <mbc/read_file.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>
#include <set>

#include "runner/run_options.h"

namespace mbc::driver {

namespace {

struct Cell {
  std::string text;
  int column = 0; // 1-based character column where the cell starts
};

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) {
    return "";
  }
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

/// Splits one line into cells at `separator`; false on an unterminated
/// quote.
bool splitLine(std::string_view line, char separator, std::vector<Cell>& cells,
               int& badColumn) {
  cells.clear();
  std::size_t i = 0;
  while (true) {
    Cell cell{"", static_cast<int>(i) + 1};
    const std::size_t start = line.find_first_not_of(" \t", i);
    if (start != std::string_view::npos && line[start] == '"') {
      std::size_t j = start + 1;
      while (true) {
        if (j >= line.size()) {
          badColumn = static_cast<int>(start) + 1;
          return false;
        }
        if (line[j] == '"') {
          if (j + 1 < line.size() && line[j + 1] == '"') {
            cell.text += '"';
            j += 2;
            continue;
          }
          break;
        }
        cell.text += line[j++];
      }
      i = line.find(separator, j + 1);
    } else {
      const std::size_t comma = line.find(separator, i);
      cell.text = trim(line.substr(i, comma == std::string_view::npos
                                          ? std::string_view::npos
                                          : comma - i));
      i = comma;
    }
    cells.push_back(std::move(cell));
    if (i == std::string_view::npos) {
      return true;
    }
    ++i;
  }
}

// A header of semicolons and no commas is a table of a locale whose
// decimal separator is the comma.
char separatorOf(std::string_view header) {
  bool quoted = false;
  bool semicolon = false;
  for (const char c : header) {
    quoted = c == '"' ? !quoted : quoted;
    if (!quoted && c == ',') {
      return ',';
    }
    semicolon = semicolon || (!quoted && c == ';');
  }
  return semicolon ? ';' : ',';
}

// "12,5" in a semicolon table is 12.5.
bool parseCell(std::string text, char separator, double& value) {
  if (separator == ';' && text.find('.') == std::string::npos &&
      std::count(text.begin(), text.end(), ',') == 1) {
    text[text.find(',')] = '.';
  }
  return runner::parseNumber(text, value);
}

enum class ColumnKind { Id, Argument, Preset, Ignored };

struct Column {
  ColumnKind kind = ColumnKind::Id;
  char letter = 0;
  double variable = 0;
};

// G65's argument letters: all but G, L, N, O and P (spec, argument
// specification I).
bool isArgumentLetter(char c) {
  return c >= 'A' && c <= 'Z' && c != 'G' && c != 'L' && c != 'N' && c != 'O' &&
         c != 'P';
}

bool parseColumn(const std::string& name, Column& column, std::string& why) {
  if (name == "id" || name == "ID" || name == "Id") {
    column.kind = ColumnKind::Id;
    return true;
  }
  if (name.size() == 1) {
    const char c = static_cast<char>(name[0] & ~0x20);
    if (isArgumentLetter(c)) {
      column = {ColumnKind::Argument, c, 0};
      return true;
    }
    if (c >= 'A' && c <= 'Z') {
      why = fmt::format("'{}' is not a G65 argument (G, L, N, O and P are "
                        "not); use its variable #N instead",
                        name);
      return false;
    }
  }
  if (name.size() > 1 && name[0] == '#') {
    int number = 0;
    const char* end = name.data() + name.size();
    auto res = std::from_chars(name.data() + 1, end, number);
    if (res.ec == std::errc() && res.ptr == end && number >= 1) {
      column = {ColumnKind::Preset, 0, static_cast<double>(number)};
      return true;
    }
  }
  why = fmt::format("unknown column '{}' (a G65 argument letter such as R, "
                    "a variable such as #100, or id; --column '{}=R' maps "
                    "it, --column '{}=' ignores it)",
                    name, name, name);
  return false;
}

bool sameName(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

/// A header cell mbc cannot read: where it starts, and why.
struct HeaderProblem {
  int column;
  std::string why;
};

// The header's columns, through the --column map. Every cell that cannot
// be read is a problem, so that one run of mbc batch names them all.
bool readHeader(const std::vector<Cell>& cells, const ColumnMap& columnMap,
                std::vector<Column>& columns,
                std::vector<HeaderProblem>& problems) {
  std::set<std::string> seen;
  std::vector<bool> mapped(columnMap.size());
  for (const Cell& cell : cells) {
    std::string name = cell.text;
    bool ignored = false;
    for (std::size_t m = 0; m < columnMap.size(); ++m) {
      if (sameName(columnMap[m].first, cell.text)) {
        mapped[m] = true;
        name = columnMap[m].second;
        ignored = name.empty();
      }
    }
    Column column;
    std::string why;
    if (ignored) {
      column.kind = ColumnKind::Ignored;
    } else if (!parseColumn(name, column, why)) {
      problems.push_back({cell.column, why});
      column.kind = ColumnKind::Ignored;
      ignored = true;
    }
    const std::string key = column.kind == ColumnKind::Argument
                                ? std::string(1, column.letter)
                                : name;
    if (!ignored && !seen.insert(key).second) {
      problems.push_back(
          {cell.column, fmt::format("column '{}' appears twice", cell.text)});
    }
    columns.push_back(column);
  }
  for (std::size_t m = 0; m < columnMap.size(); ++m) {
    if (!mapped[m]) {
      problems.push_back(
          {1, fmt::format("--column {}: the header has no column '{}'",
                          columnMap[m].first, columnMap[m].first)});
    }
  }
  return problems.empty();
}

bool isIdCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
         (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
}

} // namespace

bool readBatchTable(const std::string& path, const ColumnMap& columnMap,
                    std::vector<BatchRow>& rows, std::string& error) {
  std::string content;
  if (int readError = readFile(path, content)) {
    error = fmt::format("cannot read '{}': {}", path, std::strerror(readError));
    return false;
  }
  // Excel's "CSV UTF-8" starts with a byte order mark.
  if (content.starts_with("\xEF\xBB\xBF")) {
    content.erase(0, 3);
  }
  const auto fail = [&](int line, int column, const std::string& why) {
    error = fmt::format("{}:{}:{}: {}", path, line, column, why);
    return false;
  };
  std::vector<Column> columns;
  std::vector<Cell> cells;
  std::set<std::string> ids;
  bool hasId = false;
  char separator = ',';
  std::string text;
  int lineNumber = 0, badColumn = 0;
  for (std::size_t next = 0; next < content.size();) {
    const std::size_t end = std::min(content.find('\n', next), content.size());
    text.assign(content, next, end - next);
    next = end + 1;
    ++lineNumber;
    if (!text.empty() && text.back() == '\r') {
      text.pop_back();
    }
    if (trim(text).empty()) {
      continue;
    }
    const bool header = columns.empty();
    separator = header ? separatorOf(text) : separator;
    if (!splitLine(text, separator, cells, badColumn)) {
      return fail(lineNumber, badColumn, "unterminated quoted cell");
    }
    if (header) {
      std::vector<HeaderProblem> problems;
      if (!readHeader(cells, columnMap, columns, problems)) {
        std::vector<std::string> lines;
        for (const HeaderProblem& problem : problems) {
          lines.push_back(fmt::format("{}:{}:{}: {}", path, lineNumber,
                                      problem.column, problem.why));
        }
        error = fmt::format("{}", fmt::join(lines, "\n"));
        return false;
      }
      hasId = std::any_of(columns.begin(), columns.end(), [](const Column& c) {
        return c.kind == ColumnKind::Id;
      });
      continue;
    }
    if (cells.size() != columns.size()) {
      return fail(lineNumber, 1,
                  fmt::format("{} cells, but the header names {} columns",
                              cells.size(), columns.size()));
    }
    BatchRow row;
    row.line = lineNumber;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const Cell& cell = cells[c];
      if (columns[c].kind == ColumnKind::Id) {
        const bool safe =
            !cell.text.empty() && cell.text[0] != '.' &&
            std::all_of(cell.text.begin(), cell.text.end(), isIdCharacter);
        if (!safe) {
          return fail(lineNumber, cell.column,
                      fmt::format("id '{}' is not usable in file names "
                                  "(letters, digits, '-', '_' and '.')",
                                  cell.text));
        }
        if (!ids.insert(cell.text).second) {
          return fail(lineNumber, cell.column,
                      fmt::format("id '{}' is used twice", cell.text));
        }
        row.id = cell.text;
        continue;
      }
      if (cell.text.empty() || columns[c].kind == ColumnKind::Ignored) {
        continue;
      }
      double value = 0;
      if (!parseCell(cell.text, separator, value)) {
        return fail(lineNumber, cell.column,
                    fmt::format("'{}' is not a number", cell.text));
      }
      if (columns[c].kind == ColumnKind::Argument) {
        row.args.emplace_back(columns[c].letter, value);
      } else {
        row.presets.emplace_back(columns[c].variable, value);
      }
    }
    rows.push_back(std::move(row));
  }
  if (columns.empty()) {
    error = fmt::format("{}: no header line naming the columns", path);
    return false;
  }
  if (!hasId) {
    const std::size_t width = std::to_string(rows.size()).size();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      rows[i].id = fmt::format("{:0{}}", i + 1, width);
    }
  }
  return true;
}

bool parseShard(const std::string& text, Shard& shard) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) {
    return false;
  }
  const char* begin = text.data();
  const char* end = begin + text.size();
  auto a = std::from_chars(begin, begin + slash, shard.index);
  auto b = std::from_chars(begin + slash + 1, end, shard.count);
  return a.ec == std::errc() && a.ptr == begin + slash && b.ec == std::errc() &&
         b.ptr == end && shard.count >= 1 && shard.index >= 0 &&
         shard.index < shard.count;
}

} // namespace mbc::driver
