// Blocks no path reaches (see flow_check.h).
#include "frontend/flow_check.h"

#include "frontend/called_programs.h"
#include "frontend/flow_graph.h"
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

/// Whether a block that never runs is work lost. An END alone is its
/// loop's bracket (DO2 ... GOTO 20 ... END2 leaves its loop by the GOTO),
/// and an M99 or M30 alone after an alarm or a jump is the program's end,
/// written for the reader.
bool reported(const Stmt& s) {
  const bool endAlone =
      !flowEnd(s).empty() &&
      std::all_of(s.words.begin(), s.words.end(), [](const Word& w) {
        return w.letter == 'M' || w.letter == 'N';
      });
  return s.kind != StmtKind::Empty && s.kind != StmtKind::End && !endAlone;
}

bool hasP(const Stmt& s) {
  return std::any_of(s.words.begin(), s.words.end(),
                     [](const Word& w) { return w.letter == 'P'; });
}

/// Where an M99 P of a main program goes: its label, or with a computed P
/// any label.
void mainJumps(const Program& p, int i, std::vector<int>& work) {
  const Stmt& s = p.blocks[i].stmt;
  if (flowEnd(s) != "M99" || !hasP(s)) {
    return;
  }
  if (const std::optional<int> label = literalWord(s.words, 'P')) {
    work.push_back(findSequence(p, *label, i));
    return;
  }
  for (int j = 0; j < static_cast<int>(p.blocks.size()); ++j) {
    if (p.blocks[j].seq >= 0) {
      work.push_back(j);
    }
  }
}

/// The blocks a path from `starts` reaches; in a main program, M99 P
/// jumps too.
std::vector<bool> reachedBlocks(const Program& p, std::vector<int> work,
                                bool main = false) {
  const int n = static_cast<int>(p.blocks.size());
  std::vector<bool> reached(p.blocks.size(), false);
  while (!work.empty()) {
    const int i = work.back();
    work.pop_back();
    if (i < 0 || i >= n || reached[i]) {
      continue;
    }
    reached[i] = true;
    for (const FlowEdge& edge : successors(p, i)) {
      work.push_back(edge.to);
    }
    if (main) {
      mainJumps(p, i, work);
    }
  }
  return reached;
}

void checkProgram(const Program& p, const std::vector<bool>& reached,
                  DiagnosticEngine& diags) {
  // Where a block is in error, where its flow goes is not known.
  if (std::any_of(p.blocks.begin(), p.blocks.end(),
                  [](const Block& b) { return b.alarm != AlarmId::None; })) {
    return;
  }
  const int n = static_cast<int>(p.blocks.size());
  for (int i = 0; i < n; ++i) {
    const Block& b = p.blocks[i];
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
           s.target.number == kMacroAlarmVariable;
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

/// An M99 a main program that ends with M02 or M30 reaches from its top
/// (not as the end of a subprogram an M98 Q runs): on the control it runs
/// the program again from its top.
void checkMainReturn(const Program& p, DiagnosticEngine& diags) {
  const auto end =
      std::find_if(p.blocks.begin(), p.blocks.end(), [](const Block& b) {
        const std::string e = flowEnd(b.stmt);
        return e == "M30" || e == "M02";
      });
  if (end == p.blocks.end()) {
    return;
  }
  const std::vector<bool> reached = reachedBlocks(p, {0}, true);
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    const Block& b = p.blocks[i];
    // /M99 is the operator's end of a repeating program; M99 P jumps.
    if (!reached[i] || b.skipLevel != 0 || flowEnd(b.stmt) != "M99" ||
        hasP(b.stmt)) {
      continue;
    }
    diags.report(DiagKind::MainProgramReturn, b.range, p.name);
    diags.note(DiagKind::MainProgramEnd, end->range, p.name,
               flowEnd(end->stmt));
  }
}

} // namespace

void warnFlow(const Unit& unit, DiagnosticEngine& diags) {
  const FlowEntries entries = flowEntriesOf(unit);
  const std::vector<bool> main = mainPrograms(unit);
  for (std::size_t i = 0; i < unit.programs.size(); ++i) {
    const Program& p = unit.programs[i];
    std::vector<int> starts = enteredBlocks(p, entries);
    starts.push_back(0);
    checkProgram(p, reachedBlocks(p, std::move(starts)), diags);
    if (main[i]) {
      checkMainReturn(p, diags);
    }
    checkLoops(p, diags);
  }
}

} // namespace mbc
