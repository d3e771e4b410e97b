// JSON lines for the toolpath, numbers by number_text.h: the same bytes on
// every machine, nothing allocated per number.
#include <mbc/number_text.h>
#include <mbc/toolpath_json.h>

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstring>

namespace mbc {

namespace {

const char* motionName(int kind) {
  switch (kind) {
    case MBRT_MOTION_LINEAR:
      return "linear";
    case MBRT_MOTION_CW:
      return "cw";
    case MBRT_MOTION_CCW:
      return "ccw";
    default:
      return "rapid";
  }
}

char* writeText(char* out, const char* text) {
  while (*text != '\0') {
    *out++ = *text++;
  }
  return out;
}

char* writeString(char* out, const char* text) {
  static constexpr char kHex[] = "0123456789abcdef";
  *out++ = '"';
  for (const char* c = text != nullptr ? text : ""; *c != '\0'; ++c) {
    const auto byte = static_cast<unsigned char>(*c);
    if (*c == '"' || *c == '\\') {
      *out++ = '\\';
      *out++ = *c;
    } else if (byte < 0x20) {
      out = writeText(out, "\\u00");
      *out++ = kHex[byte >> 4];
      *out++ = kHex[byte & 15];
    } else {
      *out++ = *c;
    }
  }
  *out++ = '"';
  return out;
}

char* writeKey(char* out, char prefix, char axis) {
  // Not std::tolower: the output must not depend on the C locale.
  const char lower =
      axis >= 'A' && axis <= 'Z' ? static_cast<char>(axis - 'A' + 'a') : axis;
  *out++ = ',';
  *out++ = '"';
  if (prefix != '\0') {
    *out++ = prefix;
  }
  *out++ = lower;
  *out++ = '"';
  *out++ = ':';
  return out;
}

char* writeInteger(char* out, long long value) {
  return std::to_chars(out, out + 20, value).ptr;
}

/// The record at `out`, which has toolpathJsonBound(m) characters.
char* writeToolpathJson(char* out, const mbrt_motion& m) {
  out = writeText(out, "{\"motion\":\"");
  out = writeText(out, motionName(m.kind));
  *out++ = '"';
  for (int axis = 0; axis < m.axis_count; ++axis) {
    out = writeKey(out, '\0', m.axis_names[axis]);
    out = writeTrimmedFixed(out, m.end[axis], m.decimals);
  }
  for (int axis = 0; axis < m.axis_count; ++axis) {
    out = writeKey(out, 'm', m.axis_names[axis]);
    out = writeTrimmedFixed(out, m.machine[axis], m.decimals);
  }
  if (m.kind != MBRT_MOTION_RAPID) {
    out = writeText(out, ",\"f\":");
    // A whole feed prints as its digits, as fmt's shortest form has it.
    if (!std::signbit(m.feed) && m.feed < 1e15 &&
        m.feed == std::floor(m.feed)) {
      out = writeInteger(out, static_cast<long long>(m.feed));
    } else {
      out = fmt::format_to_n(out, 40, "{}", m.feed).out;
    }
  }
  if (m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW) {
    for (int i = 0; i < 2; ++i) {
      out = writeKey(out, 'c', m.center_axes[i]);
      out = writeTrimmedFixed(out, m.center[i], m.decimals);
    }
  }
  if (m.cycle != 0) {
    out = writeText(out, ",\"cycle\":\"G");
    out = writeInteger(out, m.cycle);
    *out++ = '"';
  }
  out = writeText(out, ",\"line\":");
  out = writeInteger(out, m.line);
  out = writeText(out, ",\"prog\":");
  out = writeString(out, m.program);
  *out++ = '}';
  *out++ = '\n';
  return out;
}

} // namespace

void appendToolpathJson(std::string& out, const mbrt_motion& m) {
  // Built in place and appended once; a record of numbers past any count
  // (kilobytes) is built in the string itself.
  const std::size_t bound = toolpathJsonBound(m);
  char line[2048];
  if (bound <= sizeof line) {
    out.append(line, writeToolpathJson(line, m));
    return;
  }
  const std::size_t start = out.size();
  out.resize(start + bound);
  const char* end = writeToolpathJson(out.data() + start, m);
  out.resize(static_cast<std::size_t>(end - out.data()));
}

std::size_t toolpathJsonBound(const mbrt_motion& m) {
  constexpr std::size_t kInteger = 20; // a long long's digits and sign
  std::size_t bytes = sizeof "{\"motion\":\"rapid\"" - 1;
  for (int axis = 0; axis < m.axis_count; ++axis) {
    bytes += sizeof ",\"mx\":" - 1 + trimmedFixedBound(m.end[axis], m.decimals);
    bytes +=
        sizeof ",\"mx\":" - 1 + trimmedFixedBound(m.machine[axis], m.decimals);
  }
  bytes += sizeof ",\"f\":" - 1 + 40; // fmt's shortest form: 25
  for (int i = 0; i < 2; ++i) {
    bytes += sizeof ",\"cx\":" - 1 + trimmedFixedBound(m.center[i], m.decimals);
  }
  bytes += sizeof ",\"cycle\":\"G\"" - 1 + kInteger;
  bytes += sizeof ",\"line\":" - 1 + kInteger;
  // "\u00xx" is the longest a character of the name becomes.
  const std::size_t name = m.program != nullptr ? std::strlen(m.program) : 0;
  bytes += sizeof ",\"prog\":\"\"}\n" - 1 + 6 * name;
  return bytes;
}

std::string toolpathJsonLine(const mbrt_motion& m) {
  std::string out;
  appendToolpathJson(out, m);
  return out;
}

} // namespace mbc
