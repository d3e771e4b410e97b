// The flow between the blocks of a program as mbc check's analyses see it:
// where each block may go next, and which blocks code elsewhere may enter
// (a label an M99 P or M98 Q names, any label when a GOTO is computed, the
// blocks a lathe's shape cycle runs). Needs the GOTO targets and loops the
// semantic checks resolve.
#pragma once

#include "frontend/ast.h"

#include <set>
#include <string>
#include <vector>

namespace mbc {

/// The labels code elsewhere may jump to, over the whole unit.
struct FlowEntries {
  std::set<int> labels;
  bool everyLabel = false;
};

FlowEntries flowEntriesOf(const Unit& unit);

/// The blocks of `p` other than its first that a path may start at.
std::vector<int> enteredBlocks(const Program& p, const FlowEntries& entries);

/// What ends the flow at a block (M30, M02, M99, #3000), or "" when it
/// goes on.
std::string flowEnd(const Stmt& s);

/// One way out of a block.
struct FlowEdge {
  int to = 0;
  const Expr* cond = nullptr; // the condition this edge takes as `outcome`
  bool outcome = true;
  bool skipped = false; // block skip left the block out
};

/// Where block `i` of `p` may go next: an index past the last block is
/// the end of the program's text.
std::vector<FlowEdge> successors(const Program& p, int i);

/// Whether `s` has the word `letter` with the constant `code`.
bool hasCode(const Stmt& s, char letter, double code);

} // namespace mbc
