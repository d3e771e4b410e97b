// --trace lines. Every engine gets the same text from the same code: the
// runtime traces what passes through it (NC blocks, G65 calls, DPRNT,
// BPRNT, POPEN, PCLOS), and statements the engines run themselves
// (assignments, IF, WHILE, END, GOTO) come as a template with values
// (mbrt_trace_values), built by frontend/trace_text.h.
#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/value.h>

#include <fmt/format.h>

#include <optional>

#include "context.h"

using namespace mbc;
using namespace mbc::rt;

namespace {

/// The name a call by name was written with, for the number it carries.
const std::string* calledName(const mbrt_ctx& ctx, mbrt_num value) {
  const std::optional<int> n = calledProgramNumber(numeric(value));
  if (!n || !isNamedProgramNumber(*n)) {
    return nullptr;
  }
  const auto it = ctx.host.programNames.find(*n);
  return it == ctx.host.programNames.end() ? nullptr : &it->second;
}

/// Whether the block's P names a program.
bool namesProgramByP(const mbrt_word* words, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    if (callsByP(words[i].letter, numeric(words[i].value))) {
      return true;
    }
  }
  return false;
}

void appendWords(const mbrt_ctx& ctx, std::string& out, const mbrt_word* words,
                 size_t count) {
  const bool call = namesProgramByP(words, count);
  for (size_t i = 0; i < count; ++i) {
    out += out.empty() ? "" : " ";
    const std::string* name = call && words[i].letter == 'P'
                                  ? calledName(ctx, words[i].value)
                                  : nullptr;
    out += name != nullptr ? *name
                           : fmt::format("{}{}", addressText(words[i].letter),
                                         words[i].value);
  }
}

} // namespace

void mbrt_trace_values(mbrt_ctx* ctx, const char* tmpl, const mbrt_num* values,
                       size_t count) {
  if (ctx->host.traceSink.fn == nullptr) {
    return;
  }
  std::string text;
  size_t next = 0;
  for (const char* p = tmpl; *p != '\0'; ++p) {
    std::string_view rest(p);
    const char* hole = rest.starts_with("{}")    ? "{}"
                       : rest.starts_with("{#}") ? "{#}"
                       : rest.starts_with("{?}") ? "{?}"
                                                 : nullptr;
    if (hole == nullptr) {
      text += *p;
      continue;
    }
    p += std::char_traits<char>::length(hole) - 1;
    const mbrt_num v = next < count ? values[next++] : 0.0;
    if (hole[1] == '?') {
      text += v != 0.0 ? "true" : "false";
    } else if (hole[1] == '#') {
      text += fmt::format("{}", roundHalfAway(numeric(v)));
    } else {
      text += isVacant(v) ? std::string("<vacant>") : fmt::format("{}", v);
    }
  }
  mbrt_trace(ctx, text.c_str());
}

void mbrt_trace_words(mbrt_ctx* ctx, const char* head, const mbrt_word* words,
                      size_t count) {
  if (ctx->host.traceSink.fn == nullptr) {
    return;
  }
  std::string text = head != nullptr ? head : "";
  appendWords(*ctx, text, words, count);
  mbrt_trace(ctx, text.c_str());
}

void mbrt_trace_call(mbrt_ctx* ctx, mbrt_num program, mbrt_num repeat,
                     const mbrt_word* words, size_t count) {
  if (ctx->host.traceSink.fn == nullptr) {
    return;
  }
  const std::string* name = calledName(*ctx, program);
  const std::string head = fmt::format(
      "G65 {} L{}",
      name != nullptr ? *name : fmt::format("P{}", numeric(program)),
      numeric(repeat));
  mbrt_trace_words(ctx, head.c_str(), words, count);
}

int mbrt_tracing(const mbrt_ctx* ctx) {
  return ctx->host.traceSink.fn != nullptr;
}

void mbrt_trace(mbrt_ctx* ctx, const char* text) {
  if (ctx->host.traceSink.fn == nullptr) {
    return;
  }
  const std::string line =
      locationPrefix(ctx->run.block.file != nullptr ? ctx->run.block.file : "",
                     ctx->run.block.line) +
      (text != nullptr ? text : "") + "\n";
  sendText(*ctx, ctx->host.traceSink, line);
}
