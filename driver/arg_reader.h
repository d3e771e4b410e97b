// Walks a command line: options with values written `--name value` or
// `--name=value`, and positional arguments.
#pragma once

#include <string>

namespace mbc::driver {

class ArgReader {
public:
  ArgReader(int argc, char** argv, int first)
      : argc_(argc), argv_(argv), next_(first) {}

  /// Moves to the next argument; false at the end.
  bool advance();

  /// The current argument's name: the whole argument, or the part before
  /// '=' of a `--name=value`.
  const std::string& name() const { return name_; }

  const std::string& arg() const { return arg_; }

  bool hasInlineValue() const { return inline_; }

  std::string inlineValue() const { return value_; }

  /// The option's value (inline or the next argument); false with a
  /// message when there is none.
  bool takeValue(std::string& value, std::string& error);

private:
  int argc_;
  char** argv_;
  int next_;
  std::string arg_;
  std::string name_;
  std::string value_;
  bool inline_ = false;
};

} // namespace mbc::driver
