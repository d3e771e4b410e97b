// Prints the control's tables as mbc holds them, as JSON, for
// tools/control_tables.py, which writes and checks docs/control-tables.md
// from them: the G code lists of both series, the system variable map, a
// lathe's offset variables, the profile's parameters and the functions.

#include <mbc/sysvars.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <tuple>
#include <vector>

#include "g_codes.h"
#include "lathe_offset_vars.h"
#include "parameters.h"
#include "sysvars.h"

namespace {

using nlohmann::json;

/// One JSON object per row of a table.
template <class Rows, class Row> json each(const Rows& rows, Row row) {
  json out = json::array();
  for (const auto& r : rows) {
    out.push_back(row(r));
  }
  return out;
}

json functions() {
  json rows = json::array();
#define BUILTIN(Id, Name, Arity)                                               \
  rows.push_back({{"name", Name}, {"arity", Arity}});
#include <mbc/builtins.def>
  // Read by the parser itself, with its bit and axis forms.
  rows.push_back({{"name", "PRM"}, {"arity", 1}});
  return rows;
}

/// The G code list of a mill (by number) or a lathe (in system A's order,
/// the codes system A lacks last), as the manuals print them.
json gCodes(bool lathe) {
  using mbc::rt::GCodeRow;
  using mbc::rt::kNo;
  std::vector<GCodeRow> rows;
  for (const GCodeRow& row : mbc::rt::gCodeRows()) {
    if (lathe ? row.a != kNo || row.b != kNo || row.c != kNo : row.m != kNo) {
      rows.push_back(row);
    }
  }
  std::sort(rows.begin(), rows.end(),
            [&](const GCodeRow& x, const GCodeRow& y) {
              return lathe ? std::tuple(x.a == kNo, x.a, x.b) <
                                 std::tuple(y.a == kNo, y.a, y.b)
                           : x.m < y.m;
            });
  return each(rows, [&](const GCodeRow& row) -> json {
    json out = lathe ? json{{"a", row.a}, {"b", row.b}, {"c", row.c}}
                     : json{{"tenths", row.m}};
    out["modelled"] = row.modelled;
    out["name"] = row.name;
    return out;
  });
}

} // namespace

int main() {
  using namespace mbc::rt;
  const json tables{
      {"gcodes_m", gCodes(false)},
      {"gcodes_t", gCodes(true)},
      {"system_variables",
       each(mbc::systemVariableRows(),
            [](const mbc::SystemVariableFacts& row) -> json {
              return {{"first", row.first},
                      {"last", row.last},
                      {"meaning", row.meaning},
                      {"modelled", row.readable},
                      {"writable", row.writable},
                      {"by_profile", row.byProfile},
                      {"note", row.note != nullptr ? row.note : ""},
                      {"unit", row.unit != nullptr ? row.unit : ""}};
            })},
      {"lathe_offsets", each(latheOffsetVariables(),
                             [](const LatheOffsetVariables& row) -> json {
                               return {{"short_base", row.shortBase},
                                       {"short_count", row.shortCount},
                                       {"long_base", row.longBase},
                                       {"key", row.key}};
                             })},
      {"parameters", each(parameterSpecs(),
                          [](const ParameterSpec& spec) -> json {
                            return {{"first", spec.first}, {"last", spec.last}};
                          })},
      {"functions", functions()}};
  std::cout << tables.dump(1) << "\n";
  return 0;
}
