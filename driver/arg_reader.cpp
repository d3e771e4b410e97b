#include "driver/arg_reader.h"

#include <fmt/format.h>

namespace mbc::driver {

bool ArgReader::advance() {
  if (next_ >= argc_) {
    return false;
  }
  arg_ = argv_[next_++];
  auto eq = arg_.find('=');
  inline_ = arg_.starts_with("--") && eq != std::string::npos;
  name_ = inline_ ? arg_.substr(0, eq) : arg_;
  value_ = inline_ ? arg_.substr(eq + 1) : std::string();
  return true;
}

bool ArgReader::takeValue(std::string& value, std::string& error) {
  if (inline_) {
    value = value_;
    return true;
  }
  if (next_ >= argc_) {
    error = fmt::format("option {} needs a value", name_);
    return false;
  }
  value = argv_[next_++];
  return true;
}

} // namespace mbc::driver
