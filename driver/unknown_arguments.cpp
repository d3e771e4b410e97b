#include "driver/unknown_arguments.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "toolchain/closest_match.h"

namespace mbc::driver {

namespace {

// "--toolpath=x" is the option "--toolpath"; "-j2" is "-j" with its value.
std::string optionName(const std::string& arg) {
  if (arg.starts_with("--")) {
    return arg.substr(0, arg.find('='));
  }
  return arg.substr(0, 2);
}

std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : command.get_options()) {
    for (const std::string& n : opt->get_lnames()) {
      names.push_back("--" + n);
    }
    for (const std::string& n : opt->get_snames()) {
      names.push_back("-" + n);
    }
  }
  return names;
}

std::string commandList(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += i == 0 ? "" : i + 1 == names.size() ? " and " : ", ";
    out += "mbc " + names[i];
  }
  return out;
}

} // namespace

std::string unknownOptionMessage(const CLI::App& root, const CLI::App& command,
                                 const std::string& arg) {
  const std::string name = optionName(arg);
  const std::string self = command.get_name();
  std::vector<std::string> owners;
  for (const CLI::App* other : root.get_subcommands({})) {
    if (other != &command && other->get_option_no_throw(name) != nullptr) {
      owners.push_back(other->get_name());
    }
  }
  if (!owners.empty()) {
    std::string message =
        fmt::format("'{}' is not an option of mbc {} (it is one of {})", name,
                    self, commandList(owners));
    // The outputs of a single run: a batch has them per row.
    if (self == "batch" && owners == std::vector<std::string>{"run"}) {
      message += ": mbc batch writes each row's toolpath, DPRNT, variables "
                 "and log under --out DIR";
    }
    return message;
  }
  // A one-letter option is too short to guess from; "-toolpath" is
  // "--toolpath" with a dash missing.
  const std::string guess = toolchain::closestMatch(
      arg.starts_with("--") ? name : arg.substr(0, arg.find('=')),
      optionNames(command));
  return fmt::format(
      "unknown option '{}' for mbc {}{}", arg, self,
      guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess));
}

std::string unknownCommandMessage(const CLI::App& root,
                                  const std::string& name) {
  std::vector<std::string> names;
  for (const CLI::App* command : root.get_subcommands({})) {
    names.push_back(command->get_name());
  }
  const std::string guess = toolchain::closestMatch(name, names);
  if (!guess.empty()) {
    return fmt::format("unknown command '{}'; did you mean '{}'?", name, guess);
  }
  std::string list;
  for (const std::string& n : names) {
    list += (list.empty() ? "" : ", ") + n;
  }
  return fmt::format("unknown command '{}' (commands: {})", name, list);
}

} // namespace mbc::driver
