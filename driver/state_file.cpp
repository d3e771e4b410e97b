// The state file. Every value lives at a variable number: the commons, the
// work offsets at #5201 (external), #5221 + 20 k (G54..G59) and #14001 +
// 20 (n - 1) (G54.1 Pn), the tool offsets at #10001 (H wear), #11001 (H
// geometry), #12001 (D wear), #13001 (D geometry). Loading writes only what
// differs, so the flattened program gets G10 blocks for real changes only.
#include "driver/state_file.h"

#include "driver/output_files.h"
#include <mbc/read_file.h>
#include <mbc/value.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>

namespace mbc::driver {

namespace {

using nlohmann::json;

constexpr int kG541Sets = 300;

struct ToolField {
  const char* key;
  int base;
};

constexpr ToolField kToolFields[] = {{"h_geometry", 11000},
                                     {"h_wear", 10000},
                                     {"d_geometry", 13000},
                                     {"d_wear", 12000}};

/// Every work offset set: its profile key and the number of its X.
std::vector<std::pair<std::string, int>> workOffsetSets() {
  std::vector<std::pair<std::string, int>> sets{{"EXT", 5201}};
  for (int k = 0; k < 6; ++k) {
    sets.emplace_back(fmt::format("G{}", 54 + k), 5221 + 20 * k);
  }
  for (int n = 1; n <= kG541Sets; ++n) {
    sets.emplace_back(fmt::format("G54.1P{}", n), 14001 + 20 * (n - 1));
  }
  return sets;
}

int axisCount(const mbrt_ctx* ctx) {
  mbrt_stats stats{};
  mbrt_get_stats(ctx, &stats);
  return stats.axis_count;
}

double readValue(mbrt_ctx* ctx, int number) {
  mbrt_num value = 0.0;
  mbrt_read_var(ctx, number, &value);
  return value;
}

/// The whole state as variable number -> value (vacant for unset commons).
std::map<int, double> currentState(mbrt_ctx* ctx) {
  std::map<int, double> state;
  for (int n = 500; n <= 999; ++n) {
    mbrt_num value = vacant();
    mbrt_peek_common(ctx, n, &value);
    state[n] = value;
  }
  const int axes = axisCount(ctx);
  for (const auto& [key, first] : workOffsetSets()) {
    for (int axis = 0; axis < axes; ++axis) {
      state[first + axis] = readValue(ctx, first + axis);
    }
  }
  for (int n = 1; n <= mbrt_tool_offset_count(ctx); ++n) {
    for (const ToolField& field : kToolFields) {
      state[field.base + n] = readValue(ctx, field.base + n);
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

/// The state a file asks for: the current one with every value the file
/// can hold reset (vacant, 0), then the file's values.
std::map<int, double> wantedState(mbrt_ctx* ctx, const json& root) {
  std::map<int, double> state = currentState(ctx);
  for (auto& [number, value] : state) {
    value = number <= 999 ? vacant() : 0.0;
  }
  const auto set = [&](int number, const json& value, const std::string& what) {
    if (!value.is_number() || !state.contains(number)) {
      throw std::runtime_error(fmt::format("bad value for {}", what));
    }
    state[number] = value.get<double>();
  };
  for (const auto& [key, value] : section(root, "variables").items()) {
    set(numberKey(key, "variables"), value, "variables." + key);
  }
  const auto sets = workOffsetSets();
  // Lambdas take structured bindings through init-captures: clang before 16
  // cannot capture a binding itself.
  for (const auto& [key, values] : section(root, "work_offsets").items()) {
    const auto found =
        std::find_if(sets.begin(), sets.end(),
                     [&k = key](const auto& s) { return s.first == k; });
    if (found == sets.end() || !values.is_array()) {
      throw std::runtime_error(
          fmt::format("\"work_offsets.{}\" is no work offset array", key));
    }
    for (std::size_t axis = 0; axis < values.size(); ++axis) {
      set(found->second + static_cast<int>(axis), values[axis],
          "work_offsets." + key);
    }
  }
  for (const auto& [key, entry] : section(root, "tool_offsets").items()) {
    const int number = numberKey(key, "tool_offsets");
    if (!entry.is_object()) {
      throw std::runtime_error(
          fmt::format("\"tool_offsets.{}\" must be an object", key));
    }
    for (const auto& [name, value] : entry.items()) {
      const auto field =
          std::find_if(std::begin(kToolFields), std::end(kToolFields),
                       [&n = name](const ToolField& f) { return n == f.key; });
      if (field == std::end(kToolFields)) {
        throw std::runtime_error(
            fmt::format("unknown key \"tool_offsets.{}.{}\"", key, name));
      }
      set(field->base + number, value, "tool_offsets." + key);
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
      if (key != "variables" && key != "work_offsets" &&
          key != "tool_offsets") {
        throw std::runtime_error(fmt::format("unknown key \"{}\"", key));
      }
    }
    const std::map<int, double> current = currentState(ctx);
    for (const auto& [number, value] : wantedState(ctx, root)) {
      if (!sameValue(value, current.at(number)) &&
          mbrt_write_var(ctx, number, value, nullptr) != 0) {
        throw std::runtime_error(
            fmt::format("#{} = {} is refused", number, value));
      }
    }
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  return true;
}

bool saveState(mbrt_ctx* ctx, const std::string& path) {
  const std::map<int, double> state = currentState(ctx);
  json variables = json::object();
  for (int n = 500; n <= 999; ++n) {
    if (!isVacant(state.at(n))) {
      variables[std::to_string(n)] = state.at(n);
    }
  }
  json offsets = json::object();
  const int axes = axisCount(ctx);
  for (const auto& [key, first] : workOffsetSets()) {
    json values = json::array();
    bool nonzero = false;
    for (int axis = 0; axis < axes; ++axis) {
      values.push_back(state.at(first + axis));
      nonzero = nonzero || state.at(first + axis) != 0.0;
    }
    if (nonzero) {
      offsets[key] = values;
    }
  }
  json tools = json::object();
  for (int n = 1; n <= mbrt_tool_offset_count(ctx); ++n) {
    json entry = json::object();
    for (const ToolField& field : kToolFields) {
      if (state.at(field.base + n) != 0.0) {
        entry[field.key] = state.at(field.base + n);
      }
    }
    if (!entry.empty()) {
      tools[std::to_string(n)] = entry;
    }
  }
  const json root = {{"variables", variables},
                     {"work_offsets", offsets},
                     {"tool_offsets", tools}};
  return replaceFile(path, root.dump(1) + "\n");
}

} // namespace mbc::driver
