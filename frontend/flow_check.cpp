// Blocks no path reaches (see flow_check.h).
#include "frontend/flow_check.h"

#include "frontend/sema.h"
#include <mbc/calling_codes.h>
#include <mbc/limits.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mbc {

namespace {

bool hasCode(const Stmt& s, char letter, int code) {
  for (const Word& w : s.words) {
    if (w.letter == letter && w.value->kind == ExprKind::Number &&
        w.value->number == code) {
      return true;
    }
  }
  return false;
}

/// What ends the flow at a block (M30, M02, M99), or "" when it goes on.
std::string flowEnd(const Stmt& s) {
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

bool computedGoto(const Stmt& s) {
  return (s.kind == StmtKind::Goto || s.kind == StmtKind::IfGoto) &&
         !s.gotoBlock;
}

/// The labels other code may jump to: M99 P (a return to the caller's
/// block, or a jump in a main program), M98 Q (a subprogram at a label of
/// the same program), and every label when a GOTO is computed.
struct Entries {
  std::set<int> labels;
  bool everyLabel = false;
};

Entries entriesOf(const Unit& unit) {
  Entries entries;
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

/// A lathe's shape cycle (G70-G73 P ns Q nf) runs the blocks ns to nf
/// however the flow goes around them.
void markShapes(const Program& p, std::vector<int>& work) {
  for (const Block& b : p.blocks) {
    const Stmt& s = b.stmt;
    if (s.kind != StmtKind::Nc ||
        !(hasCode(s, 'G', 70) || hasCode(s, 'G', 71) || hasCode(s, 'G', 72) ||
          hasCode(s, 'G', 73))) {
      continue;
    }
    const std::optional<int> ns = literalWord(s.words, 'P');
    const std::optional<int> nf = literalWord(s.words, 'Q');
    // The first block of the label from the top, as the cycle finds it.
    const int first = ns ? findSequence(p, *ns, -1) : -1;
    const int last = nf ? findSequence(p, *nf, -1) : -1;
    for (int i = first; first >= 0 && i <= last; ++i) {
      work.push_back(i);
    }
  }
}

bool reported(const Stmt& s) {
  return s.kind != StmtKind::Empty && s.kind != StmtKind::End;
}

void checkProgram(const Program& p, const Entries& entries,
                  DiagnosticEngine& diags) {
  const int n = static_cast<int>(p.blocks.size());
  std::vector<bool> reached(p.blocks.size(), false);
  std::vector<int> work{0};
  for (int i = 0; i < n; ++i) {
    const int seq = p.blocks[i].seq;
    if (seq >= 0 && !p.blocks[i].stmt.parameterData &&
        (entries.everyLabel || entries.labels.contains(seq))) {
      work.push_back(i);
    }
  }
  markShapes(p, work);
  while (!work.empty()) {
    const int i = work.back();
    work.pop_back();
    if (i < 0 || i >= n || reached[i]) {
      continue;
    }
    reached[i] = true;
    const Block& b = p.blocks[i];
    const Stmt& s = b.stmt;
    // A block the skip switch may leave out goes on to the next either way.
    bool next = b.skipLevel != 0 || flowEnd(s).empty();
    if (s.kind == StmtKind::Goto && s.gotoBlock) {
      work.push_back(*s.gotoBlock);
      next = b.skipLevel != 0;
    } else if (s.kind == StmtKind::IfGoto && s.gotoBlock) {
      work.push_back(*s.gotoBlock);
    } else if (s.kind == StmtKind::While && s.match >= 0 && s.cond) {
      work.push_back(s.match + 1); // the condition fails
    } else if (s.kind == StmtKind::End && s.match >= 0) {
      work.push_back(s.match); // back to the WHILE, which may leave
      next = false;
    }
    if (next) {
      work.push_back(i + 1);
    }
  }
  for (int i = 0; i < n; ++i) {
    const Block& b = p.blocks[i];
    // An END alone is the loop's bracket, not work that is lost (DO2 ...
    // GOTO 20 ... END2 leaves its loop by the GOTO).
    if (reached[i] || !reported(b.stmt) ||
        (i > 0 && !reached[i - 1] && reported(p.blocks[i - 1].stmt))) {
      continue;
    }
    // The first block of a run: say where the flow left before it.
    int before = i - 1;
    while (before >= 0 && !reached[before]) {
      --before;
    }
    diags.report(DiagKind::UnreachableBlock, b.range, p.name);
    if (before >= 0) {
      const Stmt& s = p.blocks[before].stmt;
      const std::string end = flowEnd(s);
      diags.note(DiagKind::FlowLeavesHere, p.blocks[before].range,
                 !end.empty()              ? end
                 : s.kind == StmtKind::End ? fmt::format("END{}, whose DO{} "
                                                         "loop has no WHILE",
                                                         s.loopId, s.loopId)
                                           : std::string("the GOTO"));
    }
  }
}

/// The variables a condition reads, when they are all locals or commons
/// (which only the program changes); nullopt when it reads a system
/// variable, a parameter or a variable by a computed number, which may
/// change by themselves.
std::optional<std::set<int>> plainVariables(const Expr& e) {
  std::set<int> vars;
  std::vector<const Expr*> work{&e};
  while (!work.empty()) {
    const Expr* x = work.back();
    work.pop_back();
    if (x->kind == ExprKind::Indirect || x->kind == ExprKind::Parameter ||
        (x->kind == ExprKind::Var &&
         !(isLocal(x->var) ||
           (x->var >= kFirstCommon && x->var <= kLastCommon) ||
           (x->var >= kFirstNonvolatile && x->var <= kLastNonvolatile)))) {
      return std::nullopt;
    }
    if (x->kind == ExprKind::Var) {
      vars.insert(x->var);
    }
    for (const ExprPtr& arg : x->args) {
      work.push_back(arg.get());
    }
  }
  return vars;
}

/// Whether a block of a loop's body may change `vars` or leave the loop
/// [first, last]: it writes one of them or writes by a computed number, it
/// calls a program (which may write commons, or the locals of an M98), it
/// jumps out or ends, or the control could not read it.
bool mayChangeOrLeave(const Program& p, int i, int first, int last,
                      const std::set<int>& vars) {
  const Block& b = p.blocks[i];
  const Stmt& s = b.stmt;
  if (b.alarm != AlarmId::None || s.kind == StmtKind::MacroCall) {
    return true;
  }
  if (s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen) {
    return s.target.index != nullptr || vars.contains(s.target.number) ||
           s.target.number == 3000;
  }
  if (s.kind == StmtKind::Goto || s.kind == StmtKind::IfGoto) {
    return !s.gotoBlock || *s.gotoBlock < first || *s.gotoBlock > last;
  }
  if (s.kind != StmtKind::Nc) {
    return false;
  }
  // Any code that may call a program (M98, G65, G66, a code a profile
  // makes call), or ends it.
  return std::any_of(s.words.begin(), s.words.end(), [](const Word& w) {
    return w.letter == 'M' || w.letter == 'T' || w.letter == 'S' ||
           w.letter == 'B' ||
           (w.letter == 'G' && w.value->kind != ExprKind::Number) ||
           (w.letter == 'G' && isMacroCall('G', w.value->number));
  });
}

/// A WHILE whose condition nothing in the loop can change, and that
/// nothing leaves: once entered it runs forever.
void checkLoops(const Program& p, DiagnosticEngine& diags) {
  for (int i = 0; i < static_cast<int>(p.blocks.size()); ++i) {
    const Stmt& s = p.blocks[i].stmt;
    if (s.kind != StmtKind::While || !s.cond || s.match <= i ||
        p.blocks[i].alarm != AlarmId::None) {
      continue;
    }
    const std::optional<std::set<int>> vars = plainVariables(*s.cond);
    if (!vars) {
      continue;
    }
    bool changes = false;
    for (int j = i + 1; j < s.match && !changes; ++j) {
      changes = mayChangeOrLeave(p, j, i, s.match, *vars);
    }
    if (changes) {
      continue;
    }
    std::string names;
    for (const int v : *vars) {
      names += fmt::format("{}#{}", names.empty() ? "" : ", ", v);
    }
    diags.report(DiagKind::EndlessLoop, s.cond->range, s.loopId,
                 names.empty() ? std::string("its condition reads nothing")
                               : "nothing in it changes " + names);
  }
}

} // namespace

void warnUnreachableBlocks(const Unit& unit, DiagnosticEngine& diags) {
  const Entries entries = entriesOf(unit);
  for (const Program& p : unit.programs) {
    checkProgram(p, entries, diags);
    checkLoops(p, diags);
  }
}

} // namespace mbc
