// Vacant reads (see vacant_check.h).
#include "frontend/vacant_check.h"

#include "frontend/called_programs.h"
#include "frontend/flow_graph.h"
#include <mbc/addresses.h>
#include <mbc/calling_codes.h>
#include <mbc/limits.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mbc {

namespace {

enum class Origin { Start, Unpassed, Assigned };

/// `#to = #from` on the way from where the vacancy began.
struct Copy {
  SourceRange range;
  int to = 0;
  int from = 0;
};

/// What is known of one local at a point of a program: whether a path
/// brings it there surely vacant, and whether a path brings anything else
/// (a number, or a value from outside the program). The default is
/// "nothing known".
struct Fact {
  bool vacant = false;
  bool other = true;
  Origin origin = Origin::Start;
  int var = 0;       // the local the vacancy began in
  SourceRange where; // Assigned: the `#n = #0`
  std::vector<Copy> copies;
  // The last condition a surely vacant value passed, on the path that
  // makes it "sometimes" vacant.
  const Expr* branch = nullptr;
  bool branchOutcome = true;
};

struct State {
  bool reached = false;
  std::array<Fact, kLocalCount> locals{};
};

Fact vacantFrom(Origin origin, int var, SourceRange where = {}) {
  Fact f;
  f.vacant = true;
  f.other = false;
  f.origin = origin;
  f.var = var;
  f.where = where;
  return f;
}

/// Joins `from` into `into`; whether `into` changed. The notes of the
/// first vacant path to arrive are kept.
bool merge(State& into, const State& from) {
  if (!from.reached) {
    return false;
  }
  if (!into.reached) {
    into = from;
    return true;
  }
  bool changed = false;
  for (std::size_t k = 0; k < into.locals.size(); ++k) {
    Fact& a = into.locals[k];
    const Fact& b = from.locals[k];
    const bool vacant = a.vacant || b.vacant;
    const bool other = a.other || b.other;
    if (vacant == a.vacant && other == a.other) {
      continue;
    }
    if (!a.vacant) {
      a = b;
    }
    a.vacant = vacant;
    a.other = other;
    changed = true;
  }
  return changed;
}

/// The local a bare `#n` reads, or 0.
int bareLocal(const Expr& e) {
  return e.isBareVariable() && e.kind == ExprKind::Var && isLocal(e.var) ? e.var
                                                                         : 0;
}

/// Whether `e` is `#0`, the variable that is always vacant.
bool isNull(const Expr& e) {
  return e.isBareVariable() && e.kind == ExprKind::Var && e.var == 0;
}

/// The local `e` tests against #0 (`#n EQ #0`, `#0 NE #n`), or 0.
int vacancyTest(const Expr& e) {
  if (e.kind != ExprKind::Compare ||
      (e.relOp != RelOp::Eq && e.relOp != RelOp::Ne)) {
    return 0;
  }
  if (isNull(*e.args[1])) {
    return bareLocal(*e.args[0]);
  }
  return isNull(*e.args[0]) ? bareLocal(*e.args[1]) : 0;
}

/// What `cond` being `outcome` says of vacancy: a local it proves set.
/// False when that cannot be, as the local is vacant on every path here:
/// no run takes this way.
bool assume(State& st, const Expr& cond, bool outcome) {
  if (cond.kind == ExprKind::Logical) {
    if ((cond.binOp == BinOp::And && outcome) ||
        (cond.binOp == BinOp::Or && !outcome)) {
      bool possible = true;
      for (const ExprPtr& arg : cond.args) {
        possible = assume(st, *arg, outcome) && possible;
      }
      return possible;
    }
    return true;
  }
  const int n = vacancyTest(cond);
  if (n == 0 || (cond.relOp == RelOp::Eq) == outcome) {
    return true;
  }
  Fact& f = st.locals[n - 1];
  const bool possible = !(f.vacant && !f.other);
  f = Fact{};
  return possible;
}

/// `st` after a condition of the flow is taken as `outcome`.
void passCondition(State& st, const Expr& cond, bool outcome) {
  for (Fact& f : st.locals) {
    if (f.vacant && !f.other) {
      f.branch = &cond;
      f.branchOutcome = outcome;
    }
  }
  st.reached = assume(st, cond, outcome);
}

void forgetLocals(State& st) {
  st.locals.fill(Fact{});
}

void assign(State& st, const Stmt& s, SourceRange block) {
  if (s.target.index) {
    forgetLocals(st);
    return;
  }
  const int n = s.target.number;
  if (!isLocal(n)) {
    return;
  }
  Fact& target = st.locals[n - 1];
  const Expr& value = *s.value;
  if (const int from = bareLocal(value)) {
    Fact copied = st.locals[from - 1];
    if (copied.vacant) {
      copied.copies.push_back({block, n, from});
    }
    target = copied;
  } else if (isNull(value)) {
    target = vacantFrom(Origin::Assigned, n, block);
  } else {
    target = Fact{};
  }
}

/// What the unit's calls say of its programs.
struct Calls {
  // Per macro: its G65/G66 calls and the locals one of them passes.
  std::map<std::string, std::vector<const Block*>, std::less<>> macroCalls;
  std::map<std::string, std::bitset<kLocalCount>, std::less<>> passed;
  std::set<std::string, std::less<>> subprograms; // called by M98/M198
  bool computedMacroCall = false;
  bool codesWriteLocals = false;
};

bool isMacroCallStmt(const Stmt& s) {
  if (s.kind == StmtKind::MacroCall) {
    return true;
  }
  return s.kind == StmtKind::Nc &&
         std::any_of(s.words.begin(), s.words.end(), [](const Word& w) {
           return w.value->kind == ExprKind::Number &&
                  isMacroCall(w.letter, w.value->number);
         });
}

Calls callsOf(const Unit& unit) {
  Calls calls;
  for (const Program& p : unit.programs) {
    calls.codesWriteLocals =
        calls.codesWriteLocals || codeMayCallSubprogram(p.number);
    for (const Block& b : p.blocks) {
      const Stmt& s = b.stmt;
      const bool macro = isMacroCallStmt(s);
      const std::optional<ProgramCall> call = programCallOf(s);
      if (!call) {
        calls.computedMacroCall = calls.computedMacroCall || macro;
        continue;
      }
      for (const CalledProgram& callee : call->programs) {
        if (!macro) {
          calls.subprograms.insert(callee.name);
          continue;
        }
        calls.macroCalls[callee.name].push_back(&b);
        std::bitset<kLocalCount>& passed = calls.passed[callee.name];
        // G66.1 passes the words of every later block.
        if (hasCode(s, 'G', 66.1)) {
          passed.set();
        }
        for (const int local : argumentLocals(callArguments(s))) {
          if (local >= 1 && local <= kLocalCount) {
            passed.set(static_cast<std::size_t>(local - 1));
          }
        }
      }
    }
  }
  return calls;
}

/// Whether an NC block may run a subprogram on the program's locals.
bool maySetLocals(const Stmt& s, const Calls& calls) {
  if (s.kind != StmtKind::Nc) {
    return false;
  }
  return std::any_of(s.words.begin(), s.words.end(), [&](const Word& w) {
    const bool constant = w.value->kind == ExprKind::Number;
    if (w.letter == 'M' && constant && isSubprogramCall('M', w.value->number)) {
      return true;
    }
    return calls.codesWriteLocals &&
           (letterMayCall(w.letter) ||
            (w.letter == 'M' && (!constant || mCodeMayCall(w.value->number))));
  });
}

/// The state after block `s` runs.
State transfer(State st, const Block& b, const Calls& calls) {
  const Stmt& s = b.stmt;
  if (s.kind == StmtKind::Assign) {
    assign(st, s, b.range);
  } else if (s.kind == StmtKind::IfThen) {
    State taken = st;
    taken.reached = assume(taken, *s.cond, true);
    assign(taken, s, b.range);
    st.reached = assume(st, *s.cond, false);
    merge(st, taken); // either side may be a way no run takes
  } else if (maySetLocals(s, calls)) {
    forgetLocals(st);
  }
  return st;
}

/// The letter, or I J K member, a G65 argument sets local `n` with.
std::string argumentName(int n) {
  for (char c = 'A'; c <= 'Z'; ++c) {
    if (argumentLocal(c) == n) {
      return std::string(1, c);
    }
  }
  return fmt::format("the {} of I J K set {}", "IJK"[(n - 4) % 3],
                     (n - 4) / 3 + 1);
}

void collectLocals(const Expr& e, std::vector<const Expr*>& out) {
  if (e.kind == ExprKind::Var && isLocal(e.var)) {
    out.push_back(&e);
  }
  for (const ExprPtr& arg : e.args) {
    collectLocals(*arg, out);
  }
}

/// The variable of a word that is one (`X#1`, `X-#1`), else nullptr.
const Expr* wordVariable(const Word& w) {
  if (!w.bareVariable) {
    return nullptr;
  }
  const Expr* e = w.value.get();
  return e->kind == ExprKind::Neg ? e->args[0].get() : e;
}

/// Every expression block `s` reads, with the address word it is the value
/// of (nullptr for none).
std::vector<std::pair<const Expr*, const Word*>> readsOf(const Stmt& s) {
  std::vector<std::pair<const Expr*, const Word*>> reads;
  for (const Word& w : s.words) {
    reads.emplace_back(w.value.get(), &w);
  }
  for (const ExprPtr* e :
       {&s.value, &s.cond, &s.target.index, &s.program, &s.repeat}) {
    if (*e) {
      reads.emplace_back(e->get(), nullptr);
    }
  }
  for (const PrintItem& item : s.items) {
    if (item.value) {
      reads.emplace_back(item.value.get(), nullptr);
    }
  }
  return reads;
}

class ProgramCheck {
public:
  ProgramCheck(const Program& p, bool main, const FlowEntries& entries,
               const Calls& calls, DiagnosticEngine& diags, bool run,
               std::uint64_t given)
      : p_(p), main_(main), run_(run), given_(given), calls_(calls),
        diags_(diags), in_(p.blocks.size()), entered_(p.blocks.size(), false),
        tested_(testedLocals(p)), loopWrites_(loopWrites(p, calls)) {
    for (const int i : enteredBlocks(p, entries)) {
      entered_[static_cast<std::size_t>(i)] = true;
      in_[static_cast<std::size_t>(i)].reached = true;
    }
  }

  void run() {
    if (p_.blocks.empty()) {
      return;
    }
    startState();
    solve();
    for (std::size_t i = 0; i < p_.blocks.size(); ++i) {
      if (in_[i].reached) {
        report(p_.blocks[i], in_[i]);
      }
    }
  }

private:
  void startState() {
    State start;
    start.reached = true;
    const auto passed = calls_.passed.find(p_.name);
    const auto given = [&](int n) { return (given_ >> (n - 1) & 1) != 0; };
    if (main_ || (run_ && passed == calls_.passed.end())) {
      for (int n = 1; n <= kLocalCount; ++n) {
        if (!given(n)) {
          start.locals[n - 1] = vacantFrom(Origin::Start, n);
        }
      }
    } else if (passed != calls_.passed.end() && !calls_.computedMacroCall &&
               !calls_.subprograms.contains(p_.name) &&
               !codeMayCallProgram(p_.number)) {
      for (int n = 1; n <= kLocalCount; ++n) {
        if (!passed->second.test(static_cast<std::size_t>(n - 1)) &&
            !given(n)) {
          start.locals[n - 1] = vacantFrom(Origin::Unpassed, n);
        }
      }
    }
    if (!entered_[0]) {
      forget(start, loopWrites_[0]);
      in_[0] = start;
    }
  }

  void solve() {
    const std::size_t n = p_.blocks.size();
    std::deque<std::size_t> work;
    std::vector<bool> queued(n, false);
    for (std::size_t i = 0; i < n; ++i) {
      if (in_[i].reached) {
        work.push_back(i);
        queued[i] = true;
      }
    }
    while (!work.empty()) {
      const std::size_t i = work.front();
      work.pop_front();
      queued[i] = false;
      const int at = static_cast<int>(i);
      const State out = transfer(in_[i], p_.blocks[i], calls_);
      for (const FlowEdge& edge : successors(p_, at)) {
        const auto to = static_cast<std::size_t>(edge.to);
        if (to >= n || entered_[to]) {
          continue;
        }
        State next = edge.skipped ? in_[i] : out;
        if (edge.cond != nullptr) {
          passCondition(next, *edge.cond, edge.outcome);
        }
        forget(next, loopWrites_[to]);
        if (merge(in_[to], next) && !queued[to]) {
          work.push_back(to);
          queued[to] = true;
        }
      }
    }
  }

  void report(const Block& b, State st) {
    const Stmt& s = b.stmt;
    if (s.kind == StmtKind::IfThen) {
      // Its value is read only then.
      if (!assume(st, *s.cond, true)) {
        return;
      }
    }
    for (const auto& [expr, word] : readsOf(s)) {
      std::vector<const Expr*> vars;
      collectLocals(*expr, vars);
      for (const Expr* var : vars) {
        const Fact& f = st.locals[static_cast<std::size_t>(var->var - 1)];
        if (!f.vacant) {
          continue;
        }
        if (f.origin == Origin::Unpassed) {
          // A macro that sets the local on some path has a default.
          if (!f.other) {
            reportUnpassed(*var);
          }
        } else if (word != nullptr) {
          reportAddress(*var, *word, f);
        }
      }
    }
  }

  void reportAddress(const Expr& var, const Word& w, const Fact& f) {
    const std::string address = addressText(w.letter);
    const std::string outcome =
        w.bareVariable && wordVariable(w) == &var
            ? fmt::format("the block has no {} word (a vacant variable drops "
                          "its address)",
                          address)
            : fmt::format("it reads as 0 in {}", address);
    diags_.report(f.other ? DiagKind::MaybeVacantAddress
                          : DiagKind::VacantAddress,
                  var.range, var.var, outcome);
    if (f.origin == Origin::Start) {
      // The program's name, not the comment after it.
      const SourceRange name{
          p_.range.begin, std::min(p_.range.length,
                                   static_cast<std::uint32_t>(p_.name.size()))};
      diags_.note(DiagKind::VacantAtStart, name, f.var, p_.name);
    } else {
      diags_.note(DiagKind::VacantAssigned, f.where, f.var);
    }
    for (const Copy& c : f.copies) {
      diags_.note(DiagKind::VacantCopied, c.range, c.to, c.from);
    }
    if (f.other && f.branch != nullptr) {
      diags_.note(DiagKind::VacantOnPath, f.branch->range,
                  f.copies.empty() ? f.var : f.copies.back().to,
                  f.branchOutcome ? "true" : "false");
    }
  }

  void reportUnpassed(const Expr& var) {
    const auto n = static_cast<std::size_t>(var.var - 1);
    if (unpassedReported_.test(n) || tested_.test(n)) {
      return;
    }
    unpassedReported_.set(n);
    diags_.report(DiagKind::UnpassedArgument, var.range, p_.name, var.var,
                  argumentName(var.var));
    for (const Block* call : calls_.macroCalls.at(p_.name)) {
      diags_.note(DiagKind::CalledWithout, call->range, p_.name,
                  argumentName(var.var));
    }
  }

  /// Per block that a way back enters (a WHILE, a backward GOTO's label),
  /// the locals its loop writes. Their facts are forgotten there: a value
  /// one round of a loop sets for the next (the previous point of a path)
  /// is vacant only on a first round that the loop's own conditions
  /// usually rule out, which this analysis cannot see.
  static std::vector<std::bitset<kLocalCount>> loopWrites(const Program& p,
                                                          const Calls& calls) {
    // The writes of blocks j to i, for every way back from i to j, as a
    // sparse table: level k holds the writes of the 2^k blocks from each,
    // so that a program with many long jumps back is not read again for
    // each (50 000 GOTOs took seconds).
    const std::size_t n = p.blocks.size();
    std::vector<std::vector<std::uint64_t>> table(
        1, std::vector<std::uint64_t>(n));
    for (std::size_t j = 0; j < n; ++j) {
      table[0][j] = writtenBy(p.blocks[j].stmt, calls).to_ullong();
    }
    for (std::size_t k = 1; (std::size_t{1} << k) <= n; ++k) {
      const std::size_t half = std::size_t{1} << (k - 1);
      std::vector<std::uint64_t>& level = table.emplace_back(n - 2 * half + 1);
      for (std::size_t j = 0; j < level.size(); ++j) {
        level[j] = table[k - 1][j] | table[k - 1][j + half];
      }
    }
    const auto writtenFrom = [&](std::size_t first, std::size_t last) {
      std::size_t k = 0;
      while ((std::size_t{2} << k) <= last - first + 1) {
        ++k;
      }
      return table[k][first] | table[k][last + 1 - (std::size_t{1} << k)];
    };
    std::vector<std::bitset<kLocalCount>> writes(n);
    for (int i = 0; i < static_cast<int>(n); ++i) {
      for (const FlowEdge& edge : successors(p, i)) {
        if (edge.to >= 0 && edge.to <= i) {
          const auto to = static_cast<std::size_t>(edge.to);
          writes[to] |= std::bitset<kLocalCount>(
              writtenFrom(to, static_cast<std::size_t>(i)));
        }
      }
    }
    return writes;
  }

  /// The locals a block may write.
  static std::bitset<kLocalCount> writtenBy(const Stmt& s, const Calls& calls) {
    std::bitset<kLocalCount> written;
    if (s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen) {
      if (s.target.index) {
        written.set();
      } else if (isLocal(s.target.number)) {
        written.set(static_cast<std::size_t>(s.target.number - 1));
      }
    } else if (maySetLocals(s, calls)) {
      written.set();
    }
    return written;
  }

  static void forget(State& st, const std::bitset<kLocalCount>& locals) {
    for (std::size_t k = 0; k < st.locals.size(); ++k) {
      if (locals.test(k)) {
        st.locals[k] = Fact{};
      }
    }
  }

  /// The locals the program tests against #0 somewhere.
  static std::bitset<kLocalCount> testedLocals(const Program& p) {
    std::bitset<kLocalCount> tested;
    std::vector<const Expr*> work;
    for (const Block& b : p.blocks) {
      for (const auto& [expr, word] : readsOf(b.stmt)) {
        work.push_back(expr);
      }
    }
    while (!work.empty()) {
      const Expr* e = work.back();
      work.pop_back();
      if (const int n = vacancyTest(*e)) {
        tested.set(static_cast<std::size_t>(n - 1));
      }
      for (const ExprPtr& arg : e->args) {
        work.push_back(arg.get());
      }
    }
    return tested;
  }

  const Program& p_;
  const bool main_;
  // Run as the main program with arguments (mbc check --arg): the locals
  // they set.
  const bool run_;
  const std::uint64_t given_;
  const Calls& calls_;
  DiagnosticEngine& diags_;
  std::vector<State> in_;
  std::vector<bool> entered_;
  const std::bitset<kLocalCount> tested_;
  const std::vector<std::bitset<kLocalCount>> loopWrites_;
  std::bitset<kLocalCount> unpassedReported_;
};

} // namespace

void warnVacantReads(const Unit& unit, DiagnosticEngine& diags,
                     const MainArguments& arguments) {
  const FlowEntries entries = flowEntriesOf(unit);
  const Calls calls = callsOf(unit);
  const std::vector<bool> main = mainPrograms(unit);
  for (std::size_t i = 0; i < unit.programs.size(); ++i) {
    const bool run = static_cast<int>(i) == arguments.program;
    ProgramCheck(unit.programs[i], main[i], entries, calls, diags, run,
                 run ? arguments.locals : 0)
        .run();
  }
}

} // namespace mbc
