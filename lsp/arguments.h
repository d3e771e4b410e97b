// Macro arguments in the editor: at each read of #1-#26 in a macro, the
// letter of specification I that sets it (inlay hints), and in a G65 or
// G66 being written, the letters the macro it calls reads (signature
// help).
#pragma once

#include "frontend/ast.h"

#include <optional>
#include <string>
#include <vector>

#include "lsp/ast_lookup.h"

namespace mbc::lsp {

struct ArgumentHint {
  std::uint32_t offset; // after the variable
  char letter;
};

/// The hints of the programs of source `file` that are no main programs,
/// between the offsets `begin` and `end`.
std::vector<ArgumentHint> argumentHints(const Unit& unit, std::uint32_t file,
                                        std::uint32_t begin, std::uint32_t end);

struct Signature {
  std::string label; // "O9040(CORNER) X Y"
  std::vector<std::string> letters;
  int active = -1; // the letter being written, -1 for none
};

/// When `found` is in a G65 or G66 of a program the unit has: the letters
/// that program reads.
std::optional<Signature> signatureAt(const Found& found, const Unit& unit,
                                     std::string_view text,
                                     std::uint32_t offset);

} // namespace mbc::lsp
