// File URIs (see uri.h).
#include "lsp/uri.h"

#include <fmt/format.h>

#include <cctype>

namespace mbc::lsp {

namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') {
    return c - '0';
  }
  const int lower = std::tolower(static_cast<unsigned char>(c));
  return lower >= 'a' && lower <= 'f' ? lower - 'a' + 10 : -1;
}

} // namespace

std::optional<std::string> pathOfUri(std::string_view uri) {
  constexpr std::string_view kScheme = "file://";
  if (uri.substr(0, kScheme.size()) != kScheme) {
    return std::nullopt;
  }
  uri.remove_prefix(kScheme.size());
  // "file://host/path": only the local host is a path here.
  if (uri.substr(0, 9) == "localhost") {
    uri.remove_prefix(9);
  }
  if (uri.empty() || uri.front() != '/') {
    return std::nullopt;
  }
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      path.push_back(uri[i]);
      continue;
    }
    const int high = i + 2 < uri.size() ? hexValue(uri[i + 1]) : -1;
    const int low = i + 2 < uri.size() ? hexValue(uri[i + 2]) : -1;
    if (high < 0 || low < 0) {
      return std::nullopt;
    }
    path.push_back(static_cast<char>(high * 16 + low));
    i += 2;
  }
  return path;
}

std::string nameOfUri(std::string_view uri) {
  return pathOfUri(uri).value_or(std::string(uri));
}

std::string uriOfPath(std::string_view path) {
  std::string uri = "file://";
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) ||
        std::string_view("/-._~").find(c) != std::string_view::npos) {
      uri.push_back(c);
    } else {
      uri += fmt::format("%{:02X}", u);
    }
  }
  return uri;
}

} // namespace mbc::lsp
