// The state file. It names every value as the machine profile does
// ("variables", "work_offsets", "tool_offsets" with the profile's keys) and
// says which machine it is for ("series", "unit"); the runtime reads and
// writes the offsets in the machine's unit (runtime.h, "The offset memory
// in the machine's unit"), so that a run ending in G20 saves millimetres on
// a metric machine and every value comes back exactly. Loading writes only
// what differs, so the flattened program gets G10 blocks for real changes.
#include "runner/state_file.h"

#include <mbc/engine.h>
#include <mbc/limits.h>
#include <mbc/read_file.h>
#include <mbc/value.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "runner/output_files.h"

namespace mbc::runner {

namespace {

using nlohmann::json;

/// What the file says of the machine it is for, and what this one is.
struct Machine {
  std::string series; // "M" or "T"
  std::string unit;   // "mm" or "inch"
  int axes = 0;
};

Machine machineOf(const mbrt_ctx* ctx) {
  mbrt_stats stats{};
  mbrt_get_stats(ctx, &stats);
  return {mbrt_lathe_system(ctx) != 0 ? "T" : "M", stats.unit,
          stats.axis_count};
}

/// One value of the state: which section, which entry, which field.
struct Place {
  enum Kind { Variable, WorkOffset, ToolOffset } kind;

  int number = 0;   // the variable, the tool offset, or the axis
  std::string name; // the work offset set, or the tool offset field
  auto operator<=>(const Place&) const = default;
};

using State = std::map<Place, double>;

double read(mbrt_ctx* ctx, const Place& place) {
  double value = vacant();
  switch (place.kind) {
    case Place::Variable:
      mbrt_peek_common(ctx, place.number, &value);
      break;
    case Place::WorkOffset:
      mbrt_get_work_offset(ctx, place.name.c_str(), place.number, &value);
      break;
    case Place::ToolOffset:
      mbrt_get_tool_offset(ctx, place.number, place.name.c_str(), &value);
      break;
  }
  return value;
}

bool write(mbrt_ctx* ctx, const Place& place, double value) {
  switch (place.kind) {
    case Place::Variable:
      return mbrt_write_var(ctx, place.number, value, nullptr) == 0;
    case Place::WorkOffset:
      return mbrt_set_work_offset(ctx, place.name.c_str(), place.number,
                                  value) != 0;
    case Place::ToolOffset:
      return mbrt_set_tool_offset(ctx, place.number, place.name.c_str(),
                                  value) != 0;
  }
  return false;
}

std::vector<std::string> toolFields(const mbrt_ctx* ctx) {
  std::vector<std::string> fields;
  for (int i = 0; const char* field = mbrt_tool_offset_field(ctx, i); ++i) {
    fields.emplace_back(field);
  }
  return fields;
}

/// Every value the state holds, as the context has it.
State currentState(mbrt_ctx* ctx) {
  State state;
  const auto add = [&](Place place) {
    const double value = read(ctx, place);
    state.emplace(std::move(place), value);
  };
  for (int n = kFirstNonvolatile; n <= kLastNonvolatile; ++n) {
    add({Place::Variable, n, ""});
  }
  const int axes = machineOf(ctx).axes;
  for (int i = 0; const char* set = mbrt_work_offset_set(i); ++i) {
    for (int axis = 0; axis < axes; ++axis) {
      add({Place::WorkOffset, axis, set});
    }
  }
  const std::vector<std::string> fields = toolFields(ctx);
  for (int n = 1; n <= mbrt_tool_offset_count(ctx); ++n) {
    for (const std::string& field : fields) {
      add({Place::ToolOffset, n, field});
    }
  }
  return state;
}

/// "512" as 512, or an error naming `what`.
int numberKey(const std::string& key, const std::string& what) {
  std::size_t end = 0;
  int n = -1;
  try {
    n = std::stoi(key, &end);
  } catch (const std::exception&) {
    end = 0;
  }
  if (end == 0 || end != key.size()) {
    throw std::runtime_error(fmt::format("unknown key \"{}.{}\"", what, key));
  }
  return n;
}

/// A section of the file, an empty object when it has none.
const json& section(const json& root, const char* key) {
  static const json empty = json::object();
  const auto it = root.find(key);
  if (it == root.end()) {
    return empty;
  }
  if (!it->is_object()) {
    throw std::runtime_error(fmt::format("\"{}\" must be an object", key));
  }
  return *it;
}

/// The file's "series" or "unit", when it gives it, must be this machine's:
/// its values are in the unit of the machine that wrote it.
void checkMachine(const json& root, const char* key, const std::string& mine) {
  const auto it = root.find(key);
  if (it == root.end()) {
    return; // a file of an earlier mbc, in this machine's unit
  }
  if (!it->is_string() || *it != mine) {
    throw std::runtime_error(
        fmt::format("\"{}\": {}: the file is for another machine (this "
                    "one's is \"{}\")",
                    key, it->dump(), mine));
  }
}

/// The state a file asks for: the current one with every value the file
/// can hold reset (vacant, 0), then the file's values.
State wantedState(mbrt_ctx* ctx, const json& root) {
  State state = currentState(ctx);
  for (auto& [place, value] : state) {
    value = place.kind == Place::Variable ? vacant() : 0.0;
  }
  const auto set = [&](const Place& place, const json& value,
                       const std::string& what) {
    if (!value.is_number() || !state.contains(place)) {
      throw std::runtime_error(fmt::format("bad value for {}", what));
    }
    state[place] = value.get<double>();
  };
  for (const auto& [key, value] : section(root, "variables").items()) {
    set({Place::Variable, numberKey(key, "variables"), ""}, value,
        "variables." + key);
  }
  for (const auto& [key, values] : section(root, "work_offsets").items()) {
    const std::string what = "work_offsets." + key;
    if (!values.is_array() || !state.contains({Place::WorkOffset, 0, key})) {
      throw std::runtime_error(
          fmt::format("\"{}\" is no work offset array", what));
    }
    for (std::size_t axis = 0; axis < values.size(); ++axis) {
      set({Place::WorkOffset, static_cast<int>(axis), key}, values[axis], what);
    }
  }
  for (const auto& [key, entry] : section(root, "tool_offsets").items()) {
    const int number = numberKey(key, "tool_offsets");
    if (!entry.is_object()) {
      throw std::runtime_error(
          fmt::format("\"tool_offsets.{}\" must be an object", key));
    }
    for (const auto& [name, value] : entry.items()) {
      const Place place{Place::ToolOffset, number, name};
      if (!state.contains(place)) {
        throw std::runtime_error(
            fmt::format("unknown key \"tool_offsets.{}.{}\"", key, name));
      }
      set(place, value, "tool_offsets." + key);
    }
  }
  return state;
}

bool sameValue(double a, double b) {
  return (isVacant(a) && isVacant(b)) || a == b;
}

} // namespace

bool loadState(mbrt_ctx* ctx, const std::string& path, std::string& error) {
  std::string text;
  if (int readError = readFile(path, text)) {
    if (readError == ENOENT) {
      return true; // the first run makes the file
    }
    error = std::strerror(readError);
    return false;
  }
  try {
    const json root = json::parse(text);
    if (!root.is_object()) {
      throw std::runtime_error("the top level must be an object");
    }
    for (const auto& [key, value] : root.items()) {
      if (key != "series" && key != "unit" && key != "variables" &&
          key != "work_offsets" && key != "tool_offsets") {
        throw std::runtime_error(fmt::format("unknown key \"{}\"", key));
      }
    }
    const Machine machine = machineOf(ctx);
    checkMachine(root, "series", machine.series);
    checkMachine(root, "unit", machine.unit);
    const State current = currentState(ctx);
    for (const auto& [place, value] : wantedState(ctx, root)) {
      if (!sameValue(value, current.at(place)) && !write(ctx, place, value)) {
        throw std::runtime_error(
            place.kind == Place::Variable
                ? fmt::format("#{} = {} is refused", place.number, value)
                : fmt::format("{} {} = {} is refused",
                              place.kind == Place::WorkOffset
                                  ? "work offset " + place.name
                                  : "tool offset " +
                                        std::to_string(place.number),
                              place.kind == Place::WorkOffset
                                  ? "axis " + std::to_string(place.number)
                                  : place.name,
                              value));
      }
    }
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  return true;
}

bool saveState(mbrt_ctx* ctx, const std::string& path) {
  json variables = json::object();
  json offsets = json::object();
  json tools = json::object();
  for (const auto& [place, value] : currentState(ctx)) {
    switch (place.kind) {
      case Place::Variable:
        if (!isVacant(value)) {
          variables[std::to_string(place.number)] = value;
        }
        break;
      case Place::WorkOffset: {
        // A set is saved whole when any axis is off zero.
        json& set = offsets[place.name];
        set.push_back(value);
        break;
      }
      case Place::ToolOffset:
        if (value != 0.0) {
          tools[std::to_string(place.number)][place.name] = value;
        }
        break;
    }
  }
  for (auto it = offsets.begin(); it != offsets.end();) {
    const bool zero = std::all_of(it->begin(), it->end(),
                                  [](const json& v) { return v == 0.0; });
    it = zero ? offsets.erase(it) : std::next(it);
  }
  const Machine machine = machineOf(ctx);
  const json root = {{"series", machine.series},
                     {"unit", machine.unit},
                     {"variables", variables},
                     {"work_offsets", offsets},
                     {"tool_offsets", tools}};
  return replaceFile(path, root.dump(1) + "\n");
}

} // namespace mbc::runner
