// What mbc says about an argument it does not know: the commands that take
// an option, or the word that was probably meant.
#pragma once

#include <string>

namespace CLI {
class App;
} // namespace CLI

namespace mbc::driver {

/// The message for an option that `command` (a command of `root`) does not
/// take: the commands that do, or "did you mean" one of its own.
std::string unknownOptionMessage(const CLI::App& root, const CLI::App& command,
                                 const std::string& arg);

/// The message for a command `root` does not have.
std::string unknownCommandMessage(const CLI::App& root,
                                  const std::string& name);

} // namespace mbc::driver
