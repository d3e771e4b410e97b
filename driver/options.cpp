// Command-line parsing for the mbc driver. Numbers are read with from_chars so
// that the locale never changes their meaning.
#include "driver/options.h"

#include <fmt/format.h>

#include <charconv>
#include <cstring>

namespace mbc::driver {

namespace {

bool parseNumber(std::string_view text, double& out) {
  if (!text.empty() && text[0] == '+') {
    text.remove_prefix(1);
  }
  auto res = std::from_chars(text.data(), text.data() + text.size(), out);
  return res.ec == std::errc() && res.ptr == text.data() + text.size();
}

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

} // namespace

std::string usageText() {
  return "usage: mbc run FILE... [--main O1234] [--engine interp]\n"
         "                [--toolpath PATH] [--dprnt PATH] [--vars-out PATH]\n"
         "                [--set '#N=V']... [--arg A=1.5]... [--machine PATH]\n"
         "                [--max-blocks N] [--block-skip[=N]] [--trace]\n"
         "       mbc check FILE...\n"
         "       mbc emit-ir FILE... [--no-opt]\n";
}

std::optional<Options> parseOptions(int argc, char** argv, std::string& error) {
  Options o;
  if (argc < 2) {
    error = "missing command";
    return std::nullopt;
  }
  o.command = argv[1];
  if (o.command != "run" && o.command != "check" && o.command != "emit-ir") {
    error = fmt::format("unknown command '{}'", o.command);
    return std::nullopt;
  }
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    std::string value;
    auto eq = a.find('=');
    bool inlineValue = a.starts_with("--") && eq != std::string::npos;
    std::string name = inlineValue ? a.substr(0, eq) : a;
    auto needValue = [&]() -> bool {
      if (inlineValue) {
        value = a.substr(eq + 1);
        return true;
      }
      if (i + 1 >= argc) {
        error = fmt::format("option {} needs a value", name);
        return false;
      }
      value = argv[++i];
      return true;
    };
    if (name == "--trace") {
      o.trace = true;
    } else if (name == "--no-opt") {
      o.noOpt = true;
    } else if (name == "--block-skip") {
      double n = 1;
      if (inlineValue &&
          (!parseNumber(a.substr(eq + 1), n) || n < 1 || n > 9)) {
        error = "--block-skip takes a switch number 1 to 9";
        return std::nullopt;
      }
      o.blockSkipMask |= 1U << static_cast<unsigned>(n);
    } else if (name == "--main" || name == "--engine" || name == "--toolpath" ||
               name == "--dprnt" || name == "--vars-out" ||
               name == "--machine" || name == "--set" || name == "--arg" ||
               name == "--max-blocks") {
      if (!needValue()) {
        return std::nullopt;
      }
      if (name == "--main") {
        o.mainProgram = value;
      } else if (name == "--engine") {
        o.engine = value;
      } else if (name == "--toolpath") {
        o.toolpathPath = value;
      } else if (name == "--dprnt") {
        o.dprntPath = value;
      } else if (name == "--vars-out") {
        o.varsOutPath = value;
      } else if (name == "--machine") {
        o.machinePath = value;
      } else if (name == "--set") {
        std::pair<double, double> p;
        if (!parsePreset(value, p)) {
          error = fmt::format("--set expects '#N=V', got '{}'", value);
          return std::nullopt;
        }
        o.presets.push_back(p);
      } else if (name == "--arg") {
        std::pair<char, double> p;
        if (!parseArg(value, p)) {
          error = fmt::format("--arg expects LETTER=VALUE, got '{}'", value);
          return std::nullopt;
        }
        o.args.push_back(p);
      } else {
        double n = 0;
        if (!parseNumber(value, n) || n < 1) {
          error = fmt::format("--max-blocks expects a positive number");
          return std::nullopt;
        }
        o.maxBlocks = static_cast<std::uint64_t>(n);
      }
    } else if (a.starts_with("-") && a != "-") {
      error = fmt::format("unknown option '{}'", a);
      return std::nullopt;
    } else {
      o.files.push_back(a);
    }
  }
  if (o.files.empty()) {
    error = "no input file";
    return std::nullopt;
  }
  if (o.engine != "interp" && o.engine != "ir") {
    error = fmt::format("unknown engine '{}' (interp or ir)", o.engine);
    return std::nullopt;
  }
  if (o.trace && o.engine != "interp") {
    error = "--trace is only available with --engine interp for now";
    return std::nullopt;
  }
  return o;
}

} // namespace mbc::driver
