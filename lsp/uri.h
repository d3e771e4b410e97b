// file:// URIs and the paths they name (RFC 8089, as editors write them:
// "file:///home/a/part%201.nc").
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mbc::lsp {

/// The path of a file URI; nothing for another scheme or a bad escape.
std::optional<std::string> pathOfUri(std::string_view uri);

/// What names a document in diagnostics and alarm reports: the path of a
/// file URI, else the URI itself.
std::string nameOfUri(std::string_view uri);

/// The file URI of an absolute path, with the characters a URI cannot hold
/// escaped.
std::string uriOfPath(std::string_view path);

} // namespace mbc::lsp
