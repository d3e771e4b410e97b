// JSON lines for the toolpath. Numbers are written with fmt, which ignores
// the C locale, so the output is the same on every machine.
#include <mbc/toolpath_json.h>

#include <fmt/format.h>

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

void appendCoordinate(std::string& out, double value, int decimals) {
  out += trimmedFixed(value, decimals);
}

void appendString(std::string& out, const char* text) {
  out += '"';
  for (const char* c = text != nullptr ? text : ""; *c != '\0'; ++c) {
    const auto byte = static_cast<unsigned char>(*c);
    if (*c == '"' || *c == '\\') {
      out += '\\';
      out += *c;
    } else if (byte < 0x20) {
      out += fmt::format("\\u{:04x}", byte);
    } else {
      out += *c;
    }
  }
  out += '"';
}

void appendKey(std::string& out, char prefix, char axis) {
  out += ",\"";
  if (prefix != '\0') {
    out += prefix;
  }
  // Not std::tolower: the output must not depend on the C locale.
  out +=
      axis >= 'A' && axis <= 'Z' ? static_cast<char>(axis - 'A' + 'a') : axis;
  out += "\":";
}

} // namespace

std::string trimmedFixed(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') {
      text.pop_back();
    }
  }
  return text == "-0" ? "0" : text;
}

std::string toolpathJsonLine(const mbrt_motion& m) {
  std::string out = "{\"motion\":\"";
  out += motionName(m.kind);
  out += '"';
  for (int axis = 0; axis < m.axis_count; ++axis) {
    appendKey(out, '\0', m.axis_names[axis]);
    appendCoordinate(out, m.end[axis], m.decimals);
  }
  for (int axis = 0; axis < m.axis_count; ++axis) {
    appendKey(out, 'm', m.axis_names[axis]);
    appendCoordinate(out, m.machine[axis], m.decimals);
  }
  if (m.kind != MBRT_MOTION_RAPID) {
    out += fmt::format(",\"f\":{}", m.feed);
  }
  if (m.kind == MBRT_MOTION_CW || m.kind == MBRT_MOTION_CCW) {
    for (int i = 0; i < 2; ++i) {
      appendKey(out, 'c', m.center_axes[i]);
      appendCoordinate(out, m.center[i], m.decimals);
    }
  }
  if (m.cycle != 0) {
    out += fmt::format(",\"cycle\":\"G{}\"", m.cycle);
  }
  out += fmt::format(",\"line\":{},\"prog\":", m.line);
  appendString(out, m.program);
  out += "}\n";
  return out;
}

} // namespace mbc
