// A run's alarm: recording the first one with its block and call stack,
// the report text every engine prints, its number and code, and operator
// messages.
#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "context.h"

namespace mbc::rt {

namespace {

std::string alarmMessage(const PendingAlarm& alarm) {
  if (alarm.id == AlarmId::MacroAlarm) {
    return alarm.detail;
  }
  std::string message = alarmInfo(alarm.id).message;
  if (!alarm.detail.empty()) {
    message += ": " + alarm.detail;
  }
  return message;
}

} // namespace

size_t copyText(std::string_view text, char* buf, size_t size) {
  if (buf != nullptr && size > 0) {
    const size_t n = std::min(text.size(), size - 1);
    std::memcpy(buf, text.data(), n);
    buf[n] = '\0';
  }
  return text.size();
}

std::string locationPrefix(const std::string& file, int line) {
  return file.empty() ? "" : fmt::format("{}:{}: ", file, line);
}

mbrt_status raise(mbrt_ctx& ctx, AlarmId id, std::string_view detail,
                  int macroNumber) {
  PendingAlarm& alarm = ctx.run.alarm;
  if (alarm.id != AlarmId::None || id == AlarmId::None) {
    return static_cast<mbrt_status>(id);
  }
  alarm.id = id;
  alarm.macroNumber = macroNumber;
  alarm.detail = detail;
  // Outside any block (before a run's first, or after mbrt_run_main
  // returned) the call came from the host: say so, where a block would
  // have its file and line.
  if (ctx.run.block.file == nullptr && id != AlarmId::MacroAlarm) {
    alarm.detail += alarm.detail.empty()
                        ? "called by the host, outside any block"
                        : " (called by the host, outside any "
                          "block)";
  }
  alarm.file = ctx.run.block.file != nullptr ? ctx.run.block.file : "";
  alarm.line = ctx.run.block.line;
  alarm.stack.clear();
  const BlockPlace& cycle = ctx.run.cycleBlock;
  if (cycle.line != 0 && alarm.line != cycle.line) {
    alarm.stack.push_back(CallSite{fmt::format("G{}", ctx.run.cycleLabel),
                                   cycle.file != nullptr ? cycle.file : "",
                                   cycle.line});
  }
  for (auto call = ctx.stack.calls.rbegin(); call != ctx.stack.calls.rend();
       ++call) {
    alarm.stack.push_back(CallSite{
        call->program, call->file != nullptr ? call->file : "", call->line});
  }
  if (ctx.host.alarmSink.fn != nullptr) {
    std::string report(mbrt_alarm_report(&ctx, nullptr, 0), '\0');
    mbrt_alarm_report(&ctx, report.data(), report.size() + 1);
    callSink(ctx, [&] {
      ctx.host.alarmSink.fn(ctx.host.alarmSink.user, report.data(),
                            report.size());
    });
  }
  return static_cast<mbrt_status>(id);
}

mbrt_status raiseAt(mbrt_ctx& ctx, const BlockPlace& place, AlarmId id,
                    std::string_view detail) {
  const BlockPlace running{ctx.run.block.file, ctx.run.block.line};
  ctx.run.block.file = place.file;
  ctx.run.block.line = place.line;
  const mbrt_status status = raise(ctx, id, detail);
  ctx.run.block.file = running.file;
  ctx.run.block.line = running.line;
  return status;
}

void sendMessage(mbrt_ctx& ctx, std::string_view text) {
  if (ctx.host.messageSink.fn == nullptr) {
    return;
  }
  const std::string line =
      locationPrefix(ctx.run.block.file != nullptr ? ctx.run.block.file : "",
                     ctx.run.block.line) +
      fmt::format("message: {}\n", text);
  sendText(ctx, ctx.host.messageSink, line);
}

} // namespace mbc::rt

using namespace mbc;
using namespace mbc::rt;

mbrt_status mbrt_raise(mbrt_ctx* ctx, int alarm_id, const char* detail) {
  const auto id = static_cast<AlarmId>(alarm_id);
  return raise(*ctx, id, detail != nullptr ? detail : "");
}

int mbrt_alarm(const mbrt_ctx* ctx) {
  return static_cast<int>(ctx->run.alarm.id);
}

int mbrt_alarm_number(const mbrt_ctx* ctx) {
  const PendingAlarm& alarm = ctx->run.alarm;
  if (alarm.id == AlarmId::MacroAlarm) {
    return alarm.macroNumber;
  }
  return alarmInfo(alarm.id).number;
}

size_t mbrt_alarm_code(const mbrt_ctx* ctx, char* buf, size_t size) {
  return copyText(alarmCode(ctx->run.alarm.id, ctx->run.alarm.macroNumber), buf,
                  size);
}

size_t mbrt_alarm_report(const mbrt_ctx* ctx, char* buf, size_t size) {
  const PendingAlarm& alarm = ctx->run.alarm;
  std::string report;
  if (alarm.id != AlarmId::None) {
    const std::string message = alarmMessage(alarm);
    report =
        fmt::format("{}alarm {}{}{}\n", locationPrefix(alarm.file, alarm.line),
                    alarmCode(alarm.id, alarm.macroNumber),
                    message.empty() ? "" : ": ", message);
    for (const CallSite& site : alarm.stack) {
      report += fmt::format("  in {} called from {}:{}\n", site.program,
                            site.file, site.line);
    }
  }
  return copyText(report, buf, size);
}

size_t mbrt_alarm_message(const mbrt_ctx* ctx, char* buf, size_t size) {
  return copyText(ctx->run.alarm.id != AlarmId::None
                      ? alarmMessage(ctx->run.alarm)
                      : std::string(),
                  buf, size);
}

const char* mbrt_alarm_file(const mbrt_ctx* ctx) {
  return ctx->run.alarm.file.c_str();
}

int mbrt_alarm_line(const mbrt_ctx* ctx) {
  return ctx->run.alarm.line;
}

size_t mbrt_alarm_depth(const mbrt_ctx* ctx) {
  return ctx->run.alarm.stack.size();
}

int mbrt_alarm_call(const mbrt_ctx* ctx, size_t level, const char** program,
                    const char** file, int* line) {
  if (level >= ctx->run.alarm.stack.size()) {
    return 0;
  }
  const CallSite& site = ctx->run.alarm.stack[level];
  *program = site.program.c_str();
  *file = site.file.c_str();
  *line = site.line;
  return 1;
}
