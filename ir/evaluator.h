// The IR evaluator (--engine ir): runs a module instruction by instruction
// with the same runtime calls, in the same order, as the reference
// interpreter (interp/), so both engines give the same motion, output,
// variables and alarms. It is the baseline later passes are checked against.
#pragma once

#include "ir/ir.h"
#include <mbc/engine.h>

namespace mbc::ir {

/// Runs module.functions[mainIndex] like the interpreter runs a program
/// (after the caller's mbrt_start). Returns 0 or the alarm that stopped it.
/// Machine settings (NAT, block skip) come from the context.
mbrt_status evaluate(const Module& module, int mainIndex, mbrt_ctx* ctx);

} // namespace mbc::ir
