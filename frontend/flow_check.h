// mbc check's flow: the blocks of a program that no path reaches (after
// M30, M02, M99 or #3000, over an unconditional GOTO, after a DO loop
// without WHILE that nothing leaves), the WHILE loops that never end, and
// the M99 of a main program written to end.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

namespace mbc {

/// Warns of each run of blocks no path of its program reaches, with a note
/// at the block the flow leaves before it. Every labelled block that a
/// computed GOTO, an M99 P, an M98 Q or a lathe cycle's P-Q range may reach
/// counts as reached. Needs the GOTO targets and loops the semantic checks
/// resolve. Warns too of each WHILE whose condition reads only locals and
/// commons that nothing in the loop can change, when nothing leaves it, and
/// of each M99 (not under block skip, without P) that a main program
/// (called_programs.h) with an M02 or M30 reaches.
void warnFlow(const Unit& unit, DiagnosticEngine& diags);

} // namespace mbc
