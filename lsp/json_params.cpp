// Reading a message's parameters (see json_params.h).
#include "lsp/json_params.h"

#include <cstdint>

namespace mbc::lsp {

using nlohmann::json;

int integer(const json& object, const char* key, int otherwise) {
  if (!object.is_object() || !object.contains(key) ||
      !object[key].is_number_integer()) {
    return otherwise;
  }
  const auto value = object[key].get<std::int64_t>();
  return value >= INT32_MIN && value <= INT32_MAX ? static_cast<int>(value)
                                                  : otherwise;
}

std::optional<std::string> text(const json& object, const char* key) {
  if (!object.is_object()) {
    return std::nullopt;
  }
  const auto it = object.find(key);
  if (it == object.end() || !it->is_string()) {
    return std::nullopt;
  }
  return it->get<std::string>();
}

std::optional<Position> positionOf(const json& p) {
  if (!p.is_object() || !p.contains("line") || !p.contains("character") ||
      !p["line"].is_number_integer() || !p["character"].is_number_integer()) {
    return std::nullopt;
  }
  const auto line = p["line"].get<std::int64_t>();
  const auto character = p["character"].get<std::int64_t>();
  if (line < 0 || character < 0 || line > INT32_MAX || character > INT32_MAX) {
    return std::nullopt;
  }
  return Position{static_cast<int>(line), static_cast<int>(character)};
}

std::optional<Range> rangeOfJson(const json& r) {
  if (!r.is_object()) {
    return std::nullopt;
  }
  const std::optional<Position> start = positionOf(r.value("start", json()));
  const std::optional<Position> end = positionOf(r.value("end", json()));
  if (!start || !end) {
    return std::nullopt;
  }
  return Range{*start, *end};
}

json toJson(Position p) {
  return {{"line", p.line}, {"character", p.character}};
}

std::optional<std::string> documentUri(const json& params) {
  return params.is_object() ? text(params.value("textDocument", json()), "uri")
                            : std::nullopt;
}

} // namespace mbc::lsp
