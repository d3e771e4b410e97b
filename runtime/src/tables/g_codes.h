// The G codes of a FANUC 0i-MF (M series) and 0i-TF (T series) as one
// table (g_codes.def): which codes exist in each series and G code system,
// what they are called, which modal group each reads back in, and whether
// mbc executes it. The handlers live in machine/g_code_handlers.cpp.
#pragma once

#include <mbc/g_codes.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace mbc::rt {

/// A code missing from one series or G code system.
inline constexpr int kNo = -1;

/// A lathe's own functions execute as 10000 plus their code in system A
/// (tenths); functions a mill has too keep the mill's number.
inline constexpr int kLatheOwnCode = 10000;

constexpr int latheOwn(int aTenths) {
  return kLatheOwnCode + aTenths;
}

/// The modal state a G code sets, which #4001+ reads back.
enum class ModalField : std::uint8_t {
#define MODAL_GROUP(Field, MGroup, TGroup) Field,
#include "g_codes.def"
};

/// One row of g_codes.def.
struct GCodeRow {
  int m, a, b, c; // tenths on a mill and on a lathe in systems A, B, C
  ModalField field;
  int code; // what the handler executes (g_codes.def)
  bool modelled;
  const char* name;

  /// The code in one column: 'M' for a mill, 'A', 'B' or 'C' for a lathe's
  /// G code system; kNo for none.
  constexpr int tenths(char column) const {
    return column == 'M' ? m : column == 'A' ? a : column == 'B' ? b : c;
  }
};

/// Every row, in the order of g_codes.def.
std::span<const GCodeRow> gCodeRows();

/// The index in gCodeRows() of G<tenths> in a column ('M', 'A', 'B',
/// 'C'), or -1 for a code that column does not have: a G word's handler
/// is found by it.
int findGCodeRowIndex(char column, int tenths);

/// The row of G<tenths> in a column, or nullptr.
inline const GCodeRow* findGCodeRow(char column, int tenths) {
  const int index = findGCodeRowIndex(column, tenths);
  return index >= 0 ? &gCodeRows()[static_cast<std::size_t>(index)] : nullptr;
}

/// The row of a column that sets `field` to `code`, or nullptr.
const GCodeRow* findModalRow(char column, ModalField field, int code);

/// The modal group a field is read in on a mill or a lathe; 0 for none.
int modalGroup(ModalField field, bool lathe);

/// The field of modal group `group` on a mill or a lathe; None for none.
ModalField groupField(int group, bool lathe);

/// How a column writes the code a handler executes, in tenths; kNo where
/// it has none (a lathe's feed per minute is G98 in system A, G94 in B).
int columnTenths(char column, int code);

/// The look-ahead, AI contour control, smoothing and servo switches
/// (look_ahead.h), in tenths: group 00 codes whose words are settings, not
/// a move.
inline constexpr int kG05 = 50;
inline constexpr int kG051 = 51;
inline constexpr int kG054 = 54;
inline constexpr int kG08 = 80;

inline constexpr bool isLookAheadCode(int tenths) {
  return tenths == kG05 || tenths == kG051 || tenths == kG054 || tenths == kG08;
}

} // namespace mbc::rt
