// Command-line parsing for the mbc driver. Numbers are read with from_chars so
// that the locale never changes their meaning.
#include "driver/options.h"

#include "ir/pass_manager.h"

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

// An option that takes a value (`--set '#1=2'`, `--set='#1=2'`).
bool setValueOption(Options& o, const std::string& name,
                    const std::string& value, std::string& error) {
  if (name == "--main") {
    o.mainProgram = value;
  } else if (name == "--disable-pass") {
    if (!ir::isPassName(value)) {
      error = fmt::format("unknown pass '{}' (passes: {})", value,
                          ir::passNameList());
      return false;
    }
    o.disabledPasses.push_back(value);
  } else if (name == "-x") {
    o.language = value;
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

// The combinations of options that make no sense.
bool checkOptions(const Options& o, std::string& error) {
  if (o.files.empty()) {
    error = "no input file";
  } else if (o.engine != "interp" && o.engine != "ir" && o.engine != "jit") {
    error = fmt::format("unknown engine '{}' (interp, ir or jit)", o.engine);
  } else if (o.language != "nc" && o.language != "mbir") {
    error = fmt::format("unknown input language '{}' (nc or mbir)", o.language);
  } else if (o.language == "mbir" && o.command != "emit-ir") {
    error = "-x mbir is only available with emit-ir";
  } else {
    return true;
  }
  return false;
}

} // namespace

std::string usageText() {
  return "usage: mbc run FILE... [--main O1234] [--engine jit|interp|ir] "
         "[-O0..3]\n"
         "                [--toolpath PATH] [--dprnt PATH] [--vars-out PATH]\n"
         "                [--set '#N=V']... [--arg A=1.5]... [--machine PATH]\n"
         "                [--max-blocks N] [--block-skip[=N]] [--trace]\n"
         "                [--no-opt] [--disable-pass NAME]... [--verify-each]\n"
         "       mbc check FILE...\n"
         "       mbc emit-ir [-x nc|mbir] FILE... [--no-opt] [--trace]\n"
         "                [--disable-pass NAME]... [--verify-each]\n"
         "passes: " +
         ir::passNameList() + "\n";
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
    } else if (a.size() == 3 && a.starts_with("-O") && a[2] >= '0' &&
               a[2] <= '3') {
      o.optLevel = a[2] - '0';
    } else if (name == "--no-opt") {
      o.noOpt = true;
    } else if (name == "--verify-each") {
      o.verifyEach = true;
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
               name == "--max-blocks" || name == "--disable-pass" ||
               name == "-x") {
      if (!needValue()) {
        return std::nullopt;
      }
      if (!setValueOption(o, name, value, error)) {
        return std::nullopt;
      }
    } else if (a.starts_with("-") && a != "-") {
      error = fmt::format("unknown option '{}'", a);
      return std::nullopt;
    } else {
      o.files.push_back(a);
    }
  }
  if (!checkOptions(o, error)) {
    return std::nullopt;
  }
  return o;
}

} // namespace mbc::driver
