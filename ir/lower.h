// Lowering from the AST to the IR in memory form: one function per program,
// one IR block per source block (plus the blocks of IF/THEN and block skip),
// every variable access an ldvar/stvar/ldind/stind.
#pragma once

#include "frontend/ast.h"
#include "frontend/source.h"
#include "ir/ir.h"

namespace mbc::ir {

struct LowerOptions {
  /// Emit a `trace` before each statement the engine runs itself, with the
  /// line --trace prints for it (frontend/trace_text.h).
  bool trace = false;
};

/// Lowers every program of a checked unit (no diagnostics errors).
Module lower(const Unit& unit, const SourceManager& sources,
             const LowerOptions& options = {});

} // namespace mbc::ir
