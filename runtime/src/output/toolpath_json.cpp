// JSON lines for the toolpath, numbers by number_text.h: the same bytes on
// every machine, nothing allocated per number.
#include <mbc/number_text.h>
#include <mbc/toolpath_json.h>

#include <fmt/format.h>

#include <cmath>
#include <iterator>

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

void appendString(std::string& out, const char* text) {
  out += '"';
  for (const char* c = text != nullptr ? text : ""; *c != '\0'; ++c) {
    const auto byte = static_cast<unsigned char>(*c);
    if (*c == '"' || *c == '\\') {
      out += '\\';
      out += *c;
    } else if (byte < 0x20) {
      fmt::format_to(std::back_inserter(out), "\\u{:04x}", byte);
    } else {
      out += *c;
    }
  }
  out += '"';
}

void appendKey(std::string& out, char prefix, char axis) {
  // Not std::tolower: the output must not depend on the C locale.
  const char lower =
      axis >= 'A' && axis <= 'Z' ? static_cast<char>(axis - 'A' + 'a') : axis;
  const char key[] = {',', '"', prefix, lower, '"', ':'};
  if (prefix != '\0') {
    out.append(key, sizeof key);
  } else {
    out.append(key, 2);
    out.append(key + 3, 3);
  }
}

} // namespace

void appendToolpathJson(std::string& out, const mbrt_motion& m) {
  out += "{\"motion\":\"";
  out += motionName(m.kind);
  out += '"';
  for (int axis = 0; axis < m.axis_count; ++axis) {
    appendKey(out, '\0', m.axis_names[axis]);
    appendTrimmedFixed(out, m.end[axis], m.decimals);
  }
  for (int axis = 0; axis < m.axis_count; ++axis) {
    appendKey(out, 'm', m.axis_names[axis]);
    appendTrimmedFixed(out, m.machine[axis], m.decimals);
  }
  if (m.kind != MBRT_MOTION_RAPID) {
    out += ",\"f\":";
    // A whole feed prints as its digits, as fmt's shortest form has it.
    if (!std::signbit(m.feed) && m.feed < 1e15 &&
        m.feed == std::floor(m.feed)) {
      appendInteger(out, static_cast<long long>(m.feed));
    } else {
      char feed[40]; // the shortest text that reads back: 25 characters
      out.append(feed, fmt::format_to_n(feed, sizeof feed, "{}", m.feed).out);
    }
  }
  if (m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW) {
    for (int i = 0; i < 2; ++i) {
      appendKey(out, 'c', m.center_axes[i]);
      appendTrimmedFixed(out, m.center[i], m.decimals);
    }
  }
  if (m.cycle != 0) {
    out += ",\"cycle\":\"G";
    appendInteger(out, m.cycle);
    out += '"';
  }
  out += ",\"line\":";
  appendInteger(out, m.line);
  out += ",\"prog\":";
  appendString(out, m.program);
  out += "}\n";
}

std::string toolpathJsonLine(const mbrt_motion& m) {
  std::string out;
  appendToolpathJson(out, m);
  return out;
}

} // namespace mbc
