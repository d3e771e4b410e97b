// The hover of the language server: what mbc knows of the word, variable
// or label under the cursor, as Markdown.
#pragma once

#include <optional>
#include <string>

#include "lsp/ast_lookup.h"

namespace mbc::lsp {

struct Hover {
  std::string markdown;
  SourceRange range; // what the text is about
};

/// `latheSystem`: the profile's lathe G code system, 0 on a mill; `unit`:
/// the programs read with the document (for the calls of a macro).
std::optional<Hover> hoverAt(const Found& found, const Unit& unit,
                             std::string_view text, char latheSystem);

} // namespace mbc::lsp
