// Prints the control's tables as mbc holds them, as JSON, for
// tools/control_tables.py, which writes and checks docs/control-tables.md
// from them: the G code lists of both series, the system variable map, a
// lathe's offset variables, the profile's parameters and the functions.

#include <nlohmann/json.hpp>

#include <iostream>

#include "g_codes.h"
#include "lathe_codes.h"
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

} // namespace

int main() {
  using namespace mbc::rt;
  const json tables{
      {"gcodes_m", each(millGCodeList(),
                        [](const GCodeInfo& code) -> json {
                          return {{"tenths", code.tenths},
                                  {"modelled", code.modelled},
                                  {"name", code.name}};
                        })},
      {"gcodes_t", each(latheGCodeList(),
                        [](const LatheGCode& code) -> json {
                          return {{"a", code.a},
                                  {"b", code.b},
                                  {"c", code.c},
                                  {"modelled", code.modelled},
                                  {"name", code.name}};
                        })},
      {"system_variables",
       each(systemVariableRows(),
            [](const SystemVariableRow& row) -> json {
              return {{"first", row.first},
                      {"last", row.last},
                      {"meaning", row.meaning},
                      {"modelled", row.modelled},
                      {"writable", row.writable},
                      {"by_profile", row.byProfile},
                      {"note", row.note != nullptr ? row.note : ""}};
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
