// The flow between blocks (see flow_graph.h).
#include "frontend/flow_graph.h"

#include "frontend/sema.h"
#include <mbc/limits.h>

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace mbc {

namespace {

/// The control's own alarm stops the flow where a program writes it.

bool computedGoto(const Stmt& s) {
  return (s.kind == StmtKind::Goto || s.kind == StmtKind::IfGoto) &&
         !s.gotoBlock;
}

bool isShapeCycle(const Stmt& s) {
  return hasCode(s, 'G', 70) || hasCode(s, 'G', 71) || hasCode(s, 'G', 72) ||
         hasCode(s, 'G', 73);
}

} // namespace

bool hasCode(const Stmt& s, char letter, double code) {
  return std::any_of(s.words.begin(), s.words.end(), [&](const Word& w) {
    return w.letter == letter && w.value->kind == ExprKind::Number &&
           w.value->number == code;
  });
}

std::string flowEnd(const Stmt& s) {
  if (s.kind == StmtKind::Assign && !s.target.index &&
      s.target.number == kMacroAlarmVariable) {
    return fmt::format("#{}", kMacroAlarmVariable);
  }
  if (s.kind != StmtKind::Nc) {
    return "";
  }
  for (const int code : {30, 2, 99}) {
    if (hasCode(s, 'M', code)) {
      return fmt::format("M{:02}", code);
    }
  }
  return "";
}

FlowEntries flowEntriesOf(const Unit& unit) {
  FlowEntries entries;
  for (const Program& p : unit.programs) {
    for (const Block& b : p.blocks) {
      const Stmt& s = b.stmt;
      entries.everyLabel = entries.everyLabel || computedGoto(s);
      if (s.kind != StmtKind::Nc) {
        continue;
      }
      if (hasCode(s, 'M', 99)) {
        if (const std::optional<int> label = literalWord(s.words, 'P')) {
          entries.labels.insert(*label);
        } else if (std::any_of(s.words.begin(), s.words.end(),
                               [](const Word& w) { return w.letter == 'P'; })) {
          entries.everyLabel = true;
        }
      }
      if (hasCode(s, 'M', 98)) {
        if (const std::optional<int> label = literalWord(s.words, 'Q')) {
          entries.labels.insert(*label);
        }
      }
    }
  }
  return entries;
}

std::vector<int> enteredBlocks(const Program& p, const FlowEntries& entries) {
  std::vector<int> entered;
  for (int i = 0; i < static_cast<int>(p.blocks.size()); ++i) {
    const Block& b = p.blocks[i];
    if (b.seq >= 0 && !b.stmt.parameterData &&
        (entries.everyLabel || entries.labels.contains(b.seq))) {
      entered.push_back(i);
    }
    // A lathe's shape cycle (G70-G73 P ns Q nf) runs the blocks ns to nf
    // however the flow goes around them, from the first ns from the top.
    if (b.stmt.kind != StmtKind::Nc || !isShapeCycle(b.stmt)) {
      continue;
    }
    const std::optional<int> ns = literalWord(b.stmt.words, 'P');
    const std::optional<int> nf = literalWord(b.stmt.words, 'Q');
    const int first = ns ? findSequence(p, *ns, -1) : -1;
    const int last = nf ? findSequence(p, *nf, -1) : -1;
    for (int j = first; first >= 0 && j <= last; ++j) {
      entered.push_back(j);
    }
  }
  return entered;
}

std::vector<FlowEdge> successors(const Program& p, int i) {
  const Block& b = p.blocks[i];
  const Stmt& s = b.stmt;
  std::vector<FlowEdge> out;
  // A block the skip switch may leave out goes on to the next either way.
  if (b.skipLevel != 0) {
    out.push_back({i + 1, nullptr, true, true});
  }
  if (s.kind == StmtKind::Goto) {
    // A computed GOTO goes to a label, and every label is an entry then.
    if (s.gotoBlock) {
      out.push_back({*s.gotoBlock});
    }
  } else if (s.kind == StmtKind::IfGoto) {
    if (s.gotoBlock) {
      out.push_back({*s.gotoBlock, s.cond.get(), true});
    }
    out.push_back({i + 1, s.cond.get(), false});
  } else if (s.kind == StmtKind::While && s.match >= 0 && s.cond) {
    out.push_back({i + 1, s.cond.get(), true});
    out.push_back({s.match + 1, s.cond.get(), false});
  } else if (s.kind == StmtKind::End && s.match >= 0) {
    out.push_back({s.match}); // back to the WHILE, which may leave
  } else if (flowEnd(s).empty()) {
    out.push_back({i + 1});
  }
  return out;
}

} // namespace mbc
