// The deterministic text form of the IR (docs/ir.md, "Text form"): what
// -emit=ir writes and ir_parser reads back. The verifier quotes single
// instructions through printInst.
#pragma once

#include "ir/ir.h"
#include <mbc/arith.h>

#include <string>
#include <string_view>

namespace mbc::ir {

/// Every function of the module, separated by one empty line.
std::string print(const Module& m);

/// One function: `func @NAME [#N] "FILE" {`, its blocks, `}` and a newline.
std::string print(const Module& m, const Function& f);

/// One instruction as it appears in a block, without indentation and
/// without its `!LINE` suffix (the suffix depends on the block).
std::string printInst(const Module& m, const Function& f, ValueId id);

/// The name of a builtin in the IR: builtins.def's name, except that Atan2
/// is "ATAN2" (the source spells both ATAN).
std::string_view builtinMnemonic(Builtin b);
bool builtinFromMnemonic(std::string_view name, Builtin& out);

/// The number of rows of builtins.def.
int builtinCount();

/// "int", "dec", "val", "var", "nvar".
std::string_view wordKindName(WordKind k);
bool wordKindFromName(std::string_view name, WordKind& out);

/// The shortest text that reads back to the same double ("0.1", "1e+20").
std::string formatNumber(double v);

/// `s` in double quotes, with `"` and `\` escaped by a backslash.
std::string quoteString(std::string_view s);

} // namespace mbc::ir
