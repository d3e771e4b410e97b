// The protocol's numbers and the readers of a message's parameters that
// the server's handlers share: a member of the wrong type reads as absent,
// as the protocol allows for optional members, never as an exception.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "lsp/text_document.h"

namespace mbc::lsp {

// The protocol's error codes.
inline constexpr int kParseError = -32700;
inline constexpr int kInvalidRequest = -32600;
inline constexpr int kMethodNotFound = -32601;
inline constexpr int kInvalidParams = -32602;
inline constexpr int kServerNotInitialized = -32002;
inline constexpr int kRequestCancelled = -32800;
inline constexpr int kContentModified = -32801;

// window/logMessage and window/showMessage types.
inline constexpr int kLogError = 1;
inline constexpr int kLogWarning = 2;
inline constexpr int kLogInfo = 3;

inline constexpr int kSyncIncremental = 2;

/// An integer member of an object, or `otherwise`.
int integer(const nlohmann::json& object, const char* key, int otherwise);

/// A string member of an object, or nothing.
std::optional<std::string> text(const nlohmann::json& object, const char* key);

std::optional<Position> positionOf(const nlohmann::json& p);
std::optional<Range> rangeOfJson(const nlohmann::json& r);
nlohmann::json toJson(Position p);

/// A document the request names: params.textDocument.uri.
std::optional<std::string> documentUri(const nlohmann::json& params);

} // namespace mbc::lsp
