// The G code table (g_codes.def) and its lookups: a G word finds its row
// through one index per column, built when the runtime is compiled.
#include "g_codes.h"

#include <mbc/g_codes.h>

#include <fmt/format.h>

#include <array>

namespace mbc::rt {

namespace {

constexpr std::array kRows = {
#define G_CODE(M, A, B, C, Field, Code, Handler, Name)                         \
  GCodeRow{M, A, B, C, ModalField::Field, Code, true, Name},
#define G_UNMODELLED(M, A, B, C, Name)                                         \
  GCodeRow{M, A, B, C, ModalField::None, kNo, false, Name},
#include "g_codes.def"
};

struct GroupRow {
  ModalField field;
  int mill, lathe;
};

constexpr std::array kGroups = {
#define MODAL_GROUP(Field, MGroup, TGroup)                                     \
  GroupRow{ModalField::Field, MGroup, TGroup},
#include "g_codes.def"
};

constexpr std::array kColumns = {'M', 'A', 'B', 'C'};

constexpr std::size_t columnIndex(char column) {
  return column == 'M' ? 0 : column == 'A' ? 1 : column == 'B' ? 2 : 3;
}

// G251 (2510) is the highest code of any column.
constexpr int kMaxTenths = 2510;
constexpr std::uint8_t kNoRow = 0xff;
static_assert(kRows.size() < kNoRow);

using ColumnIndex = std::array<std::uint8_t, kMaxTenths + 1>;

constexpr ColumnIndex buildIndex(char column) {
  ColumnIndex index{};
  index.fill(kNoRow);
  for (std::size_t i = 0; i < kRows.size(); ++i) {
    if (const int tenths = kRows[i].tenths(column); tenths != kNo) {
      index.at(static_cast<std::size_t>(tenths)) = static_cast<std::uint8_t>(i);
    }
  }
  return index;
}

constexpr std::array<ColumnIndex, kColumns.size()> kIndex = {
    buildIndex('M'), buildIndex('A'), buildIndex('B'), buildIndex('C')};

/// Each code of a column names one row, and each executed code one row of
/// a column: a lookup either way finds one answer. One pass with a seen
/// mark per code keeps the check within clang's constexpr step limit.
constexpr bool columnIsUnique(char column) {
  std::array<bool, kMaxTenths + 1> seenTenths{};
  std::array<bool, kLatheOwnCode + kMaxTenths + 1> seenCode{};
  for (const GCodeRow& row : kRows) {
    const int tenths = row.tenths(column);
    if (tenths == kNo) {
      continue;
    }
    if (seenTenths.at(static_cast<std::size_t>(tenths))) {
      return false;
    }
    seenTenths.at(static_cast<std::size_t>(tenths)) = true;
    if (row.modelled) {
      if (seenCode.at(static_cast<std::size_t>(row.code))) {
        return false;
      }
      seenCode.at(static_cast<std::size_t>(row.code)) = true;
    }
  }
  return true;
}

static_assert(columnIsUnique('M') && columnIsUnique('A') &&
              columnIsUnique('B') && columnIsUnique('C'));

/// The rows of each modal field, so that a #4001+ read looks at a group's
/// few codes rather than the whole table.
struct FieldRows {
  std::array<std::uint8_t, kRows.size()> rows{};
  std::size_t count = 0;
};

constexpr auto kFieldRows = [] {
  std::array<FieldRows, kGroups.size()> fields{};
  for (std::size_t i = 0; i < kRows.size(); ++i) {
    FieldRows& field = fields[static_cast<std::size_t>(kRows[i].field)];
    field.rows[field.count++] = static_cast<std::uint8_t>(i);
  }
  return fields;
}();

} // namespace

std::span<const GCodeRow> gCodeRows() {
  return kRows;
}

int findGCodeRowIndex(char column, int tenths) {
  if (tenths < 0 || tenths > kMaxTenths) {
    return -1;
  }
  const std::uint8_t row =
      kIndex[columnIndex(column)][static_cast<std::size_t>(tenths)];
  return row != kNoRow ? row : -1;
}

const GCodeRow* findModalRow(char column, ModalField field, int code) {
  const FieldRows& rows = kFieldRows[static_cast<std::size_t>(field)];
  for (std::size_t i = 0; i < rows.count; ++i) {
    const GCodeRow& row = kRows[rows.rows[i]];
    if (row.code == code && row.tenths(column) != kNo) {
      return &row;
    }
  }
  return nullptr;
}

int modalGroup(ModalField field, bool lathe) {
  const GroupRow& row = kGroups[static_cast<std::size_t>(field)];
  return lathe ? row.lathe : row.mill;
}

ModalField groupField(int group, bool lathe) {
  for (const GroupRow& row : kGroups) {
    if (group != 0 && (lathe ? row.lathe : row.mill) == group) {
      return row.field;
    }
  }
  return ModalField::None;
}

int columnTenths(char column, int code) {
  for (const GCodeRow& row : kRows) {
    if (row.modelled && row.code == code && row.tenths(column) != kNo) {
      return row.tenths(column);
    }
  }
  return kNo;
}

} // namespace mbc::rt

std::string mbc::gCodeText(int tenths) {
  return tenths % 10 == 0 ? fmt::format("G{}", tenths / 10)
                          : fmt::format("G{}.{}", tenths / 10, tenths % 10);
}

bool mbc::isFanucGCode(int tenths) {
  return mbc::rt::findGCodeRow('M', tenths) != nullptr;
}

std::optional<mbc::GCodeFacts> mbc::gCodeFacts(char column, int tenths) {
  const mbc::rt::GCodeRow* row = mbc::rt::findGCodeRow(column, tenths);
  if (row == nullptr) {
    return std::nullopt;
  }
  return mbc::GCodeFacts{
      row->name, mbc::rt::modalGroup(row->field, column != 'M'), row->modelled};
}

std::vector<std::pair<int, mbc::GCodeFacts>> mbc::gCodeList(char column) {
  std::vector<std::pair<int, mbc::GCodeFacts>> out;
  for (const mbc::rt::GCodeRow& row : mbc::rt::gCodeRows()) {
    const int tenths = row.tenths(column);
    if (tenths != mbc::rt::kNo) {
      out.emplace_back(tenths, *mbc::gCodeFacts(column, tenths));
    }
  }
  return out;
}

const char* mbc::unmodelledGCode(int tenths) {
  const mbc::rt::GCodeRow* row = mbc::rt::findGCodeRow('M', tenths);
  return row != nullptr && !row->modelled ? row->name : nullptr;
}

int mbc::latheFunction(char system, int tenths) {
  const mbc::rt::GCodeRow* row = mbc::rt::findGCodeRow(system, tenths);
  return row != nullptr ? row->a : -1;
}

const char* mbc::unmodelledLatheFunction(int aTenths) {
  const mbc::rt::GCodeRow* row = mbc::rt::findGCodeRow('A', aTenths);
  return row != nullptr && !row->modelled ? row->name : nullptr;
}
