// The --trace line of each statement an engine runs itself, as a template
// for mbrt_trace_values: "{}" takes a value, "{#}" a variable number and
// "{?}" a truth. The interpreter fills it in as it goes; the IR lowering puts
// it in a `trace` instruction, so every engine prints the same lines.
// NC blocks, G65 calls and DPRNT/BPRNT/POPEN/PCLOS are traced by the runtime.
#pragma once

#include "frontend/ast.h"

#include <string>

namespace mbc {

/// The template for statement `s` of program `p`. Its values, in order:
/// assignment (and IF-THEN when `taken`): the variable number when written
/// #[...], then the value; IF-GOTO and WHILE: the condition's truth; a
/// computed GOTO: the target. IF-THEN not taken has none.
std::string traceTemplate(const Program& p, const Stmt& s, bool taken = true);

} // namespace mbc
