// Go to definition and the document's symbols: where a GOTO or M99 P
// lands, the program an M98/G65 P calls, and the outline of programs, N
// labels and DO loops.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lsp/ast_lookup.h"
#include "toolchain/compile_unit.h"

namespace mbc::lsp {

/// A place in one of the unit's sources.
struct Place {
  std::uint32_t file = 0;
  SourceRange range;
};

/// The number of the program a block calls with a constant P or a name
/// (M98, M198, G65, G66, G66.1; a name's number as the semantic checks
/// give it).
std::optional<int> calledNumber(const Stmt& s);

/// Where the thing at `found` is defined: the block a jump lands on, the
/// program a call names; nothing for anything else.
std::vector<Place> definitionOf(const Found& found,
                                const toolchain::CompiledUnit& cu);

/// The program and N an M99 P at `found` returns to: the N of its callers
/// (of itself when it runs as the main program); nothing for another place.
struct Return {
  int callee; // the number of the program with the M99
  int seq;
};

std::optional<Return> returnAt(const Found& found);

/// The blocks N`seq` of the programs of `unit` that call program `callee`.
std::vector<Place> returnPlaces(const Unit& unit, const Return& r);

/// Every place that names what `found` is on: a variable's reads and
/// writes (a local's in its own program, another's in every program of
/// `unit`), an N label's GOTOs, a program's calls; with `declaration`, the
/// label or the program's O line too.
std::vector<Place> referencesOf(const Found& found, const Unit& unit,
                                bool declaration);

/// What `found` names across documents: a variable other than a local,
/// or a program number (nothing for a local or a label, which belong to
/// their program).
struct SharedName {
  int variable = -1;
  int program = -1;
};

SharedName sharedNameOf(const Found& found);

/// The places of `name` in the programs of `unit` (of source `file`).
std::vector<Place> placesOf(const SharedName& name, const Unit& unit,
                            std::uint32_t file, bool declaration);

struct Symbol {
  std::string name;
  std::string detail;
  int kind;              // the protocol's SymbolKind
  SourceRange range;     // all of it
  SourceRange selection; // its name
  std::vector<Symbol> children;
};

/// The programs of source `file`, each with its N labels and DO loops.
std::vector<Symbol> documentSymbols(const toolchain::CompiledUnit& cu,
                                    std::uint32_t file);

} // namespace mbc::lsp
