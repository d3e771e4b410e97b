// Semantic checks (see sema.h).
#include "frontend/sema.h"

#include "frontend/called_programs.h"
#include "frontend/flow_check.h"
#include "frontend/vacant_check.h"
#include <mbc/addresses.h>
#include <mbc/g_codes.h>
#include <mbc/limits.h>
#include <mbc/sysvars.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string_view>

namespace mbc {

namespace {

struct Loop {
  int id;
  int block;
};

// A loop the control cannot run alarms at the block it stops at (its first
// error wins, as in the parser).
void setAlarm(Block& b, AlarmId alarm, std::string detail) {
  if (b.alarm == AlarmId::None) {
    b.alarm = alarm;
    b.alarmDetail = std::move(detail);
  }
}

void setAlarm(Block& b, Diagnostic& d) {
  setAlarm(b, runTimeAlarm(d.kind), alarmDetail(d.message));
  d.alarm = b.alarm; // the note names the alarm the block raises
}

void matchLoops(Program& p, DiagnosticEngine& diags) {
  std::vector<Loop> open;
  for (int i = 0; i < static_cast<int>(p.blocks.size()); ++i) {
    Block& b = p.blocks[i];
    Stmt& s = b.stmt;
    if (s.kind == StmtKind::While) {
      if (open.size() == static_cast<std::size_t>(kMaxLoopNesting)) {
        setAlarm(b, diags.report(DiagKind::LoopNesting, s.range,
                                 kMaxLoopNesting + 1));
      }
      // The innermost open loop of that number is the one to name, and
      // stopping there keeps thousands of nested WHILEs linear.
      for (auto l = open.rbegin(); l != open.rend(); ++l) {
        if (l->id == s.loopId) {
          setAlarm(b, diags.report(DiagKind::LoopIdReused, s.range, s.loopId));
          diags.note(DiagKind::DoOpenedHere, p.blocks[l->block].stmt.range,
                     l->id);
          break;
        }
      }
      open.push_back({s.loopId, i});
      continue;
    }
    if (s.kind != StmtKind::End) {
      continue;
    }
    int found = -1;
    for (int k = static_cast<int>(open.size()) - 1; k >= 0; --k) {
      if (open[k].id == s.loopId) {
        found = k;
        break;
      }
    }
    if (found < 0) {
      setAlarm(
          b, diags.report(DiagKind::EndWithoutDo, s.range, s.loopId, s.loopId));
      continue;
    }
    if (found != static_cast<int>(open.size()) - 1) {
      const Loop& inner = open.back();
      setAlarm(b, diags.report(DiagKind::CrossingLoops, s.range, s.loopId,
                               s.loopId, inner.id));
      diags.note(DiagKind::DoOpenedHere, p.blocks[inner.block].stmt.range,
                 inner.id);
      // The loops it crossed have lost their END.
      for (int k = found + 1; k < static_cast<int>(open.size()); ++k) {
        const int id = open[k].id;
        setAlarm(p.blocks[open[k].block], runTimeAlarm(DiagKind::DoWithoutEnd),
                 alarmDetail(fmt::vformat(formatOf(DiagKind::DoWithoutEnd),
                                          fmt::make_format_args(id, id))));
      }
    }
    Stmt& w = p.blocks[open[found].block].stmt;
    w.match = i;
    s.match = open[found].block;
    open.resize(found);
  }
  for (const Loop& l : open) {
    Block& b = p.blocks[l.block];
    setAlarm(b, diags.report(DiagKind::DoWithoutEnd, b.stmt.range, l.id, l.id));
  }
}

/// A sequence number used twice matters where a GOTO searches for it: the
/// flattened program (--gcode) keeps every N a loop ran, and has no GOTO.
void checkSequences(const Program& p, DiagnosticEngine& diags) {
  const bool searched =
      std::any_of(p.blocks.begin(), p.blocks.end(), [](const Block& b) {
        return b.stmt.kind == StmtKind::Goto || b.stmt.kind == StmtKind::IfGoto;
      });
  if (!searched) {
    return;
  }
  std::map<int, int> first;
  for (int i = 0; i < static_cast<int>(p.blocks.size()); ++i) {
    int seq = p.blocks[i].seq;
    if (seq < 0 || p.blocks[i].stmt.parameterData) {
      continue;
    }
    auto [it, inserted] = first.emplace(seq, i);
    if (!inserted) {
      diags.report(DiagKind::DuplicateSequence, p.blocks[i].range, seq, p.name);
      diags.note(DiagKind::SequenceDefinedHere, p.blocks[it->second].range,
                 seq);
    }
  }
}

bool inside(const Program& p, int block, int whileBlock) {
  int end = p.blocks[whileBlock].stmt.match;
  return end >= 0 && block > whileBlock && block <= end;
}

/// What a program's GOTOs are resolved with: its labels, and its WHILE
/// blocks (a jump into a loop is an error).
struct JumpFacts {
  SequenceIndex sequences;
  std::vector<int> whiles;

  explicit JumpFacts(const Program& p) : sequences(p) {
    for (int w = 0; w < static_cast<int>(p.blocks.size()); ++w) {
      if (p.blocks[static_cast<std::size_t>(w)].stmt.kind == StmtKind::While) {
        whiles.push_back(w);
      }
    }
  }
};

void resolveGoto(Program& p, int i, const JumpFacts& jumps,
                 DiagnosticEngine& diags) {
  Stmt& s = p.blocks[i].stmt;
  const Expr* v = s.value.get();
  bool negative = v && v->kind == ExprKind::Neg;
  if (negative) {
    v = v->args[0].get();
  }
  if (!v || v->kind != ExprKind::Number) {
    return;
  }
  const double written = negative ? -v->number : v->number;
  double n = std::round(written);
  if (!isSequenceNumber(n)) {
    diags.report(DiagKind::GotoRange, s.value->range,
                 fmt::format("{}", written), kMaxSequenceNumber);
    return;
  }
  int target = jumps.sequences.find(static_cast<int>(n), i);
  if (target < 0) {
    diags.report(DiagKind::GotoUndefined, s.value->range, n, p.name);
    return;
  }
  s.gotoBlock = target;
  for (const int w : jumps.whiles) {
    if (inside(p, target, w) && !inside(p, i, w)) {
      diags.report(DiagKind::GotoIntoLoop, s.value->range, n);
      return;
    }
  }
}

// Variables that cannot exist on the default machine are only a warning: a
// profile may add them (#200-#499, #2401-#2800), and the control alarms only
// if the block runs. With a machine profile only the runtime knows.
struct Reported {
  bool defaultMachine;
  std::set<int> numbers; // one warning per variable and program is enough
};

void warnMissing(int n, SourceRange at, Reported& reported,
                 DiagnosticEngine& diags) {
  if (!reported.defaultMachine && dependsOnProfile(n)) {
    return;
  }
  if (variableAccess(n) != VarAccess::Missing ||
      !reported.numbers.insert(n).second) {
    return;
  }
  UnmodelledVariable unmodelled{};
  if (unmodelledVariable(n, &unmodelled)) {
    diags.report(DiagKind::VariableNotModelled, at, n, unmodelled.meaning,
                 unmodelled.reason);
    return;
  }
  diags.report(DiagKind::VariableMissing, at, n);
}

void checkVariables(const Expr& e, Reported& reported,
                    DiagnosticEngine& diags) {
  if (e.kind == ExprKind::Var) {
    warnMissing(e.var, e.range, reported, diags);
  }
  for (const ExprPtr& a : e.args) {
    checkVariables(*a, reported, diags);
  }
}

void checkStatementVariables(const Stmt& s, Reported& reported,
                             DiagnosticEngine& diags) {
  for (const Expr* e : {s.value.get(), s.cond.get(), s.target.index.get(),
                        s.program.get(), s.repeat.get()}) {
    if (e) {
      checkVariables(*e, reported, diags);
    }
  }
  for (const Word& w : s.words) {
    checkVariables(*w.value, reported, diags);
  }
  for (const PrintItem& it : s.items) {
    if (it.value) {
      checkVariables(*it.value, reported, diags);
    }
  }
  bool assigns = s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen;
  if (assigns && !s.target.index) {
    warnMissing(s.target.number, s.target.range, reported, diags);
  }
}

void checkWrite(const Stmt& s, DiagnosticEngine& diags) {
  if (s.target.index) {
    return;
  }
  int n = s.target.number;
  if (n == 0) {
    diags.report(DiagKind::WriteVacant, s.target.range);
  } else if (variableAccess(n) == VarAccess::ReadOnly) {
    diags.report(DiagKind::WriteReadOnly, s.target.range, n);
  }
}

/// Programs known by name get numbers above the O numbers, in the order
/// they are defined, and each call by name its program's number. A name
/// that nothing defines raises PS0310 when its block runs, as a control
/// finds no such file.
void resolveProgramNames(Unit& unit, DiagnosticEngine& diags) {
  std::map<std::string, int, std::less<>> numbers;
  for (Program& p : unit.programs) {
    if (p.name.starts_with('<')) {
      p.number = kFirstNamedProgram + static_cast<int>(numbers.size());
      numbers.emplace(p.name, p.number);
    }
  }
  const auto resolve = [&](Block& b, const std::string& name, Expr& p) {
    if (name.empty()) {
      return;
    }
    const auto it = numbers.find(name);
    if (it == numbers.end()) {
      diags.report(DiagKind::ProgramNotFound, p.range, name,
                   alarmCode(AlarmId::FileNotFound, 0), "");
      setAlarm(b, AlarmId::FileNotFound, name);
      return;
    }
    p.number = it->second;
  };
  for (Program& p : unit.programs) {
    for (Block& b : p.blocks) {
      Stmt& s = b.stmt;
      if (s.kind == StmtKind::MacroCall && s.program) {
        resolve(b, s.calledName, *s.program);
      }
      for (Word& w : s.words) {
        resolve(b, w.calledName, *w.value);
      }
    }
  }
}

/// A call of a program number that no input and no file of the search path
/// defines raises PS0076 when its block runs: said here, where the text is.
void warnMissingNumbers(const Unit& unit, DiagnosticEngine& diags) {
  std::set<int> defined;
  for (const Program& p : unit.programs) {
    defined.insert(p.number);
  }
  for (const Program& p : unit.programs) {
    for (const Block& b : p.blocks) {
      const std::optional<ProgramCall> call = programCallOf(b.stmt);
      if (!call || call->programs.front().number < 0 ||
          std::any_of(call->programs.begin(), call->programs.end(),
                      [&](const CalledProgram& c) {
                        return defined.contains(c.number);
                      })) {
        continue;
      }
      std::string names;
      for (const CalledProgram& c : call->programs) {
        names += (names.empty() ? "" : " or ") + c.name;
      }
      // A number of five digits or more is no program on a machine of
      // 4-digit numbers (program_number_digits), which the text cannot
      // know; M98 P without L calls its low digits there instead.
      const int number = call->programs.front().number;
      const bool longNumber =
          call->programs.size() == 1 && number > kMaxProgramNumber4Digits;
      diags.report(
          DiagKind::ProgramNotFound, call->range, names,
          alarmCode(AlarmId::ProgramNotFound, 0),
          longNumber ? fmt::format("; {} on a machine with 4-digit "
                                   "program numbers",
                                   alarmCode(AlarmId::IllegalProgramNumber, 0))
                     : "");
    }
  }
}

/// Two arguments of one G65 or G66 call that set the same local: the later
/// one wins (spec §5.4), so the earlier value never reaches the macro. It
/// happens when specifications I and II mix (G65 P1000 I1. I2. D3.: the
/// second I and D are both #7) or when a letter is repeated.
void checkCallArguments(const Stmt& s, DiagnosticEngine& diags) {
  const std::vector<const Word*> args = callArguments(s);
  const std::vector<int> locals = argumentLocals(args);
  std::array<const Word*, kLocalCount + 1> setter{};
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Word* w = args[i];
    const int local = locals[i];
    if (local <= 0 || local > kLocalCount) {
      continue;
    }
    if (const Word* earlier = setter[static_cast<std::size_t>(local)]) {
      const bool ijk = w->letter >= 'I' && w->letter <= 'K';
      diags.report(DiagKind::ArgumentOverwritten, earlier->range,
                   addressText(earlier->letter), local, addressText(w->letter));
      diags.note(DiagKind::ArgumentSetAgain, w->range, addressText(w->letter),
                 local, ijk && local > 6 ? "II" : "I");
    }
    setter[static_cast<std::size_t>(local)] = w;
  }
}

} // namespace

int findSequence(const Program& program, int seq, int from) {
  return SequenceIndex(program).find(seq, from);
}

SequenceIndex::SequenceIndex(const Program& program) {
  for (int i = 0; i < static_cast<int>(program.blocks.size()); ++i) {
    if (program.blocks[static_cast<std::size_t>(i)].seq >= 0) {
      blocks_[program.blocks[static_cast<std::size_t>(i)].seq].push_back(i);
    }
  }
}

int SequenceIndex::find(int seq, int from) const {
  const auto it = blocks_.find(seq);
  if (it == blocks_.end()) {
    return -1;
  }
  // After `from` to the end, else from the top (`from` itself last).
  const auto after =
      std::upper_bound(it->second.begin(), it->second.end(), from);
  return after != it->second.end() ? *after : it->second.front();
}

std::optional<int> literalWord(const std::vector<Word>& words, char letter) {
  for (const Word& w : words) {
    if (w.letter == letter && w.value->kind == ExprKind::Number) {
      return static_cast<int>(std::lround(w.value->number));
    }
  }
  return std::nullopt;
}

bool hasLetter(const std::vector<Word>& words, std::string_view letters) {
  return std::any_of(words.begin(), words.end(), [&](const Word& w) {
    return letters.find(w.letter) != std::string_view::npos;
  });
}

// A lathe's G71/G72 whose shape starts with a block that gives the cut
// axis too (Z for G71, X for G72) cuts pockets (type II): mbc's path there
// is reconstructed from sources that are not FANUC's, which a review of
// the program should know.
void noteTypeTwo(const Program& p, int index, char system,
                 DiagnosticEngine& diags) {
  const Block& b = p.blocks[index];
  const std::vector<Word>& words = b.stmt.words;
  int code = 0; // system A's number of the cycle
  double written = 0.0;
  for (const Word& w : words) {
    if (w.letter == 'G' && w.value->kind == ExprKind::Number) {
      const int a = latheFunction(
          system, static_cast<int>(std::lround(w.value->number * 10.0)));
      if (a == 710 || a == 720) {
        code = a;
        written = w.value->number;
      }
    }
  }
  const std::optional<int> ns = literalWord(words, 'P');
  const std::optional<int> nf = literalWord(words, 'Q');
  if (code == 0 || !ns || !nf) {
    return;
  }
  const int first = findSequence(p, *ns, index);
  if (first < 0 || p.blocks[first].stmt.kind != StmtKind::Nc) {
    return;
  }
  const bool turning = code == 710;
  const std::vector<Word>& shape = p.blocks[first].stmt.words;
  if (hasLetter(shape, turning ? "ZW" : "XU") &&
      hasLetter(shape, turning ? "XU" : "ZW")) {
    diags.report(DiagKind::TypeTwoRoughing, b.range, written, *ns, *nf, *ns,
                 turning ? 'Z' : 'X');
  }
}

void checkUnit(Unit& unit, DiagnosticEngine& diags,
               const SemaOptions& options) {
  // The parser reported them; the control keeps the first program of a
  // number, and so do the calls.
  std::erase_if(unit.programs, [](const Program& p) { return p.duplicate; });
  resolveProgramNames(unit, diags);
  warnMissingNumbers(unit, diags);
  for (Program& p : unit.programs) {
    matchLoops(p, diags);
    checkSequences(p, diags);
    Reported reported{options.defaultMachine, {}};
    const JumpFacts jumps(p);
    for (int i = 0; i < static_cast<int>(p.blocks.size()); ++i) {
      Stmt& s = p.blocks[i].stmt;
      checkStatementVariables(s, reported, diags);
      checkCallArguments(s, diags);
      if (s.kind == StmtKind::Goto || s.kind == StmtKind::IfGoto) {
        resolveGoto(p, i, jumps, diags);
      } else if (s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen) {
        checkWrite(s, diags);
      } else if (s.kind == StmtKind::Nc && options.reviewNotes &&
                 options.latheSystem != 0) {
        noteTypeTwo(p, i, options.latheSystem, diags);
      }
    }
  }
  if (options.reviewNotes) {
    warnFlow(unit, diags);
    // Vacancy needs every block read: a block in error says too little.
    if (diags.totalErrors() == 0) {
      warnVacantReads(unit, diags,
                      {options.argumentProgram, options.argumentLocals});
    }
  }
}

} // namespace mbc
