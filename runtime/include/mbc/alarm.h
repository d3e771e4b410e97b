// Alarm identifiers generated from alarms.def, and their printed form
// ("PS0112", "3001", "MBC0001").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace mbc {

enum class AlarmId : std::uint16_t {
  None,
#define ALARM(Id, Prefix, Number, Message) Id,
#include <mbc/alarms.def>
};

struct AlarmInfo {
  const char* prefix;
  int number;
  const char* message;
};

/// The table row of an alarm id (AlarmId::None has an empty row).
const AlarmInfo& alarmInfo(AlarmId id);

/// "PS0112" for program alarms, "3000+n" for macro alarms, "MBC0001" for ours.
std::string alarmCode(AlarmId id, int macroNumber);

/// The alarm whose code is "PS0112" or "MBC0001"; AlarmId::None for any
/// other text (macro alarms have no fixed code).
AlarmId alarmFromCode(std::string_view code);

/// The control shows at most this many characters of a #3000 or #3006
/// message.
inline constexpr std::size_t kMessageShown = 26;

/// A #3000 or #3006 message as written in its comment, without the spaces
/// around it.
std::string_view trimmedMessage(std::string_view comment);

} // namespace mbc
