// Run options. Numbers are read with from_chars so that the locale never
// changes their meaning.
#include "driver/run_options.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace mbc::driver {

bool parseNumber(std::string_view text, double& out) {
  if (!text.empty() && text[0] == '+') {
    text.remove_prefix(1);
  }
  auto res = std::from_chars(text.data(), text.data() + text.size(), out);
  // inf and nan are no values a variable can hold (spec §2.4).
  return res.ec == std::errc() && res.ptr == text.data() + text.size() &&
         std::isfinite(out);
}

bool parseSize(std::string_view text, std::uint64_t& out) {
  double unit = 1;
  if (!text.empty()) {
    const char suffix = text.back();
    const std::string_view units = "KMGT";
    const auto pos = units.find(static_cast<char>(suffix & ~0x20));
    if (pos != std::string_view::npos) {
      unit = static_cast<double>(std::uint64_t{1} << (10 * (pos + 1)));
      text.remove_suffix(1);
    }
  }
  double n = 0;
  if (!parseNumber(text, n) || n * unit < 1 || n * unit > 0x1p63) {
    return false;
  }
  out = static_cast<std::uint64_t>(n * unit);
  return true;
}

namespace {

// "#N=V" (the '#' is optional)
bool parsePreset(std::string_view text, std::pair<double, double>& out) {
  if (!text.empty() && text[0] == '#') {
    text.remove_prefix(1);
  }
  auto eq = text.find('=');
  return eq != std::string_view::npos &&
         parseNumber(text.substr(0, eq), out.first) &&
         parseNumber(text.substr(eq + 1), out.second);
}

// "A=1.5"
bool parseArg(std::string_view text, std::pair<char, double>& out) {
  if (text.size() < 3 || text[1] != '=') {
    return false;
  }
  char c = text[0];
  if (c >= 'a' && c <= 'z') {
    c = static_cast<char>(c - 'a' + 'A');
  }
  out.first = c;
  return c >= 'A' && c <= 'Z' && parseNumber(text.substr(2), out.second);
}

bool setValue(RunOptions& o, const std::string& name, const std::string& value,
              std::string& error) {
  if (name == "--main") {
    o.mainProgram = value;
  } else if (name == "--toolpath") {
    o.toolpathPath = value;
  } else if (name == "--dprnt") {
    o.dprntPath = value;
  } else if (name == "--gcode") {
    o.gcodePath = value;
  } else if (name == "--svg") {
    o.svgPath = value;
  } else if (name == "--state") {
    o.statePath = value;
  } else if (name == "--vars-out") {
    o.varsOutPath = value;
  } else if (name == "--machine") {
    o.machinePath = value;
  } else if (name == "--set") {
    std::pair<double, double> p;
    if (!parsePreset(value, p)) {
      error = fmt::format("--set expects '#N=V', got '{}'", value);
      return false;
    }
    o.presets.push_back(p);
  } else if (name == "--arg") {
    std::pair<char, double> p;
    if (!parseArg(value, p)) {
      error = fmt::format("--arg expects LETTER=VALUE, got '{}'", value);
      return false;
    }
    o.args.push_back(p);
  } else if (name == "--max-output") {
    if (!parseSize(value, o.maxOutput)) {
      error = fmt::format("--max-output expects a size in bytes such as "
                          "4096, 64K, 512M or 2G, got '{}'",
                          value);
      return false;
    }
  } else {
    double n = 0;
    if (!parseNumber(value, n) || n < 1) {
      error = fmt::format("--max-blocks expects a positive number");
      return false;
    }
    o.maxBlocks = static_cast<std::uint64_t>(n);
  }
  return true;
}

bool takesValue(const std::string& name) {
  return name == "--main" || name == "--toolpath" || name == "--dprnt" ||
         name == "--gcode" || name == "--svg" || name == "--state" ||
         name == "--vars-out" || name == "--machine" || name == "--set" ||
         name == "--arg" || name == "--max-blocks" || name == "--max-output";
}

} // namespace

OptionStatus readRunOption(ArgReader& args, RunOptions& o, std::string& error) {
  const std::string& name = args.name();
  if (name == "--trace") {
    o.trace = true;
    return OptionStatus::Taken;
  }
  if (name == "--time") {
    o.time = true;
    return OptionStatus::Taken;
  }
  if (name == "--block-skip") {
    double n = 1;
    if (args.hasInlineValue() &&
        (!parseNumber(args.inlineValue(), n) || n < 1 || n > 9)) {
      error = "--block-skip takes a switch number 1 to 9";
      return OptionStatus::Error;
    }
    o.blockSkipMask |= 1U << static_cast<unsigned>(n);
    return OptionStatus::Taken;
  }
  if (!takesValue(name)) {
    return OptionStatus::NotARunOption;
  }
  std::string value;
  if (!args.takeValue(value, error) || !setValue(o, name, value, error)) {
    return OptionStatus::Error;
  }
  return OptionStatus::Taken;
}

std::string runOptionsUsage(int indent) {
  std::string pad(static_cast<std::size_t>(indent), ' ');
  return pad +
         "[--main O1234] [--toolpath PATH] [--dprnt PATH] [--vars-out PATH]\n" +
         pad + "[--gcode PATH] [--svg PATH] [--state PATH]\n" + pad +
         "[--set '#N=V']... [--arg A=1.5]... [--machine PATH]\n" + pad +
         "[--max-blocks N] [--max-output SIZE] [--block-skip[=N]]\n" + pad +
         "[--trace] [--time]\n";
}

} // namespace mbc::driver
