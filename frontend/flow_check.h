// mbc check's flow: the blocks of a program that no path reaches (after
// M30, M02 or M99, over an unconditional GOTO, after a DO loop without
// WHILE that nothing leaves), and the WHILE loops that never end.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

namespace mbc {

/// Warns of each run of blocks no path of its program reaches, with a note
/// at the block the flow leaves before it. Every labelled block that a
/// computed GOTO, an M99 P, an M98 Q or a lathe cycle's P-Q range may reach
/// counts as reached. Needs the GOTO targets and loops the semantic checks
/// resolve. Warns too of each WHILE whose condition reads only locals and
/// commons that nothing in the loop can change, when nothing leaves it.
void warnUnreachableBlocks(const Unit& unit, DiagnosticEngine& diags);

} // namespace mbc
