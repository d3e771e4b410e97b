// The alarm table generated from alarms.def and the codes the driver prints
// ("PS0112", "MBC0001", "3001").
#include <mbc/alarm.h>

#include <array>
#include <cctype>
#include <cstddef>

namespace mbc {

namespace {

constexpr std::array kAlarmTable = {
    AlarmInfo{"", 0, ""},
#define ALARM(Id, Prefix, Number, Message) AlarmInfo{Prefix, Number, Message},
#include <mbc/alarms.def>
};

/// FANUC shows program alarms with four digits ("PS0011"); wider numbers are
/// kept whole rather than truncated.
std::string zeroPadded(int number, std::size_t width) {
  std::string digits = std::to_string(number);
  if (digits.size() < width) {
    digits.insert(0, width - digits.size(), '0');
  }
  return digits;
}

} // namespace

const AlarmInfo& alarmInfo(AlarmId id) {
  const auto index = static_cast<std::size_t>(id);
  // An id cast from a corrupt integer must not read past the table.
  return index < kAlarmTable.size() ? kAlarmTable[index] : kAlarmTable[0];
}

std::string alarmCode(AlarmId id, int macroNumber) {
  if (id == AlarmId::None) {
    return "";
  }
  if (id == AlarmId::MacroAlarm) {
    return std::to_string(macroNumber);
  }
  const AlarmInfo& info = alarmInfo(id);
  return info.prefix + zeroPadded(info.number, 4);
}

AlarmId alarmFromCode(std::string_view code) {
  for (std::size_t i = 1; i < kAlarmTable.size(); ++i) {
    const auto id = static_cast<AlarmId>(i);
    if (id != AlarmId::MacroAlarm && alarmCode(id, 0) == code) {
      return id;
    }
  }
  return AlarmId::None;
}

std::string_view trimmedMessage(std::string_view comment) {
  while (!comment.empty() &&
         std::isspace(static_cast<unsigned char>(comment.front()))) {
    comment.remove_prefix(1);
  }
  while (!comment.empty() &&
         std::isspace(static_cast<unsigned char>(comment.back()))) {
    comment.remove_suffix(1);
  }
  return comment;
}

} // namespace mbc
