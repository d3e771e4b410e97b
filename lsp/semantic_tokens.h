// Semantic tokens: the document's words as the lexer reads them, classed
// for an editor's colours (G and M codes, variables, system variables,
// addresses, labels, functions, keywords, numbers, comments, the text of
// DPRNT and BPRNT).
#pragma once

#include "frontend/source.h"

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace mbc::lsp {

/// The legend the server announces: a token's type and modifier bits
/// index these.
inline constexpr std::array<std::string_view, 10> kTokenTypes = {
    "keyword",  "variable",  "number",   "comment", "function",
    "property", "namespace", "operator", "string",  "enumMember"};
inline constexpr std::array<std::string_view, 2> kTokenModifiers = {
    "readonly", "defaultLibrary"};

struct SemanticToken {
  std::uint32_t offset;
  std::uint32_t length;
  int type;      // index in kTokenTypes
  int modifiers; // bits of kTokenModifiers
};

/// The tokens of source `file`, in order.
std::vector<SemanticToken> semanticTokens(const SourceManager& sources,
                                          std::uint32_t file);

} // namespace mbc::lsp
