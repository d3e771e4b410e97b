// Readers for the JSON of machine profiles: each checks one value and, when
// it is wrong, throws ProfileError with a message naming its key path.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "probe_scene.h"

namespace mbc::rt {

struct ProfileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& key, const std::string& what);
[[noreturn]] void unknownKey(const std::string& path);

/// "parent.key", or "key" at the top level.
std::string child(const std::string& path, const std::string& key);

const nlohmann::json& object(const nlohmann::json& value,
                             const std::string& path);
double number(const nlohmann::json& value, const std::string& path);
int integer(const nlohmann::json& value, const std::string& path, int low,
            int high);
bool boolean(const nlohmann::json& value, const std::string& path);

/// A decimal key such as "3401" or "7"; nullopt when it is not one.
std::optional<int> keyNumber(std::string_view key);

/// The "probe" section: the stylus and the scene it can touch.
ProbeScene parseProbeScene(const nlohmann::json& value);

} // namespace mbc::rt
