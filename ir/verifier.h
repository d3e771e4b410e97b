// The IR verifier: checks the invariants of docs/ir.md ("Invariants") on a
// whole module. Runs after lowering, after every pass under -verify-each and
// before code generation.
#pragma once

#include "ir/ir.h"

#include <string>
#include <vector>

namespace mbc::ir {

/// Every broken invariant, one message each, empty when the module is valid.
/// Messages name the function, the block and the instruction:
/// "@O1000 b2: %7 = add %5, %9: operand %9 does not dominate its use".
std::vector<std::string> verify(const Module& m);

} // namespace mbc::ir
