// Reads the IR text form (docs/ir.md, "Text form") back into a Module, so
// that tests and passes can start from IR written by hand. print(parse(t))
// == t for every text the printer writes.
#pragma once

#include "ir/ir.h"

#include <string>
#include <string_view>

namespace mbc::ir {

/// Parses a module. On success replaces `out` and returns true; otherwise
/// leaves `out` alone and sets `error` to "line:col: message" (1-based,
/// columns in bytes).
///
/// Value ids are kept as written: Function::insts is sized to the largest id
/// written (defined or used) + 1, and instructions that define no value take
/// the ids after it, in text order. Unused slots stay Op::Unreachable with
/// type None and are in no block. Undefined operands and out-of-range branch
/// targets are accepted here; the verifier reports them.
bool parseModule(std::string_view text, Module& out, std::string& error);

} // namespace mbc::ir
