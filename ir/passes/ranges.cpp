// Range analysis (see ranges.h): abstract interpretation over intervals.
// The ascending phase starts from nothing known and widens a phi to an
// infinite bound once it has grown twice; the result is a post-fixpoint, so
// every range holds every value a run can produce. Two narrowing rounds then
// give back the finite bounds the loop conditions imply. Each rule follows
// the engines' arithmetic: IEEE operations are monotone, so computing the
// bounds with the same operation bounds the result; library functions are
// widened by a little, because libm need not be monotone to the last bit.
#include "ir/passes/ranges.h"

#include "ir/cfg.h"
#include "ir/passes/pass_util.h"
#include <mbc/arith.h>
#include <mbc/limits.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <unordered_map>

namespace mbc::ir {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxRounds = 100;
constexpr int kGrowthsBeforeWidening = 2;
constexpr int kNarrowingRounds = 2;

const Range kEmpty{kInf, -kInf}; // no value: not computed yet, or dead

bool isEmpty(const Range& r) {
  return r.lo > r.hi;
}

Range join(const Range& a, const Range& b) {
  return isEmpty(a)   ? b
         : isEmpty(b) ? a
                      : Range{std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

Range meet(const Range& a, const Range& b) {
  return Range{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// A bound that came out NaN (inf - inf, 0 * inf) says nothing.
Range checked(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) {
    return Range{};
  }
  return Range{lo, hi};
}

Range outward(const Range& r) {
  constexpr double kSlack = 1e-9;
  return Range{r.lo - kSlack * std::max(1.0, std::fabs(r.lo)),
               r.hi + kSlack * std::max(1.0, std::fabs(r.hi))};
}

Range multiply(const Range& a, const Range& b) {
  double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  for (double x : p) {
    if (std::isnan(x)) {
      return Range{};
    }
  }
  return Range{*std::min_element(std::begin(p), std::end(p)),
               *std::max_element(std::begin(p), std::end(p))};
}

// IEEE division is monotone in each operand on either side of a zero
// divisor, so the quotients of the bounds bound every quotient.
Range divide(const Range& a, const Range& b) {
  if (b.lo <= 0 && b.hi >= 0) {
    return Range{}; // the divisor may be 0 (an alarm) or near it
  }
  double q[] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  for (double x : q) {
    if (std::isnan(x)) {
      return Range{};
    }
  }
  return Range{*std::min_element(std::begin(q), std::end(q)),
               *std::max_element(std::begin(q), std::end(q))};
}

Range builtin(Builtin fn, const Range& a) {
  switch (fn) {
    case Builtin::Sin:
    case Builtin::Cos:
      return Range{-1, 1};
    case Builtin::Abs:
      if (a.lo >= 0) {
        return a;
      }
      return a.hi <= 0 ? Range{-a.hi, -a.lo} : Range{0, std::max(-a.lo, a.hi)};
    case Builtin::Round:
      return Range{roundHalfAway(a.lo), roundHalfAway(a.hi)};
    case Builtin::Fix:
      return Range{std::trunc(a.lo), std::trunc(a.hi)};
    case Builtin::Fup:
      return Range{a.lo < 0 ? std::floor(a.lo) : std::ceil(a.lo),
                   a.hi < 0 ? std::floor(a.hi) : std::ceil(a.hi)};
    case Builtin::Sqrt:
      return outward(Range{std::sqrt(std::max(a.lo, 0.0)), std::sqrt(a.hi)});
    default:
      return Range{};
  }
}

// `value op other` holds (op one of lt le gt ge eq, value on the left).
struct Constraint {
  BlockId block; // holds in the blocks this one dominates
  RelOp op;
  ValueId other;
};

// `b op a` for `a op b`.
RelOp mirrored(RelOp op) {
  switch (op) {
    case RelOp::Lt:
      return RelOp::Gt;
    case RelOp::Le:
      return RelOp::Ge;
    case RelOp::Gt:
      return RelOp::Lt;
    case RelOp::Ge:
      return RelOp::Le;
    case RelOp::Eq:
    case RelOp::Ne:
      break;
  }
  return op;
}

// The comparison that holds when `op` is false (on numbers, never NaN).
RelOp negated(RelOp op) {
  switch (op) {
    case RelOp::Lt:
      return RelOp::Ge;
    case RelOp::Le:
      return RelOp::Gt;
    case RelOp::Gt:
      return RelOp::Le;
    case RelOp::Ge:
      return RelOp::Lt;
    case RelOp::Eq:
      return RelOp::Ne;
    case RelOp::Ne:
      break;
  }
  return RelOp::Eq;
}

class Analysis {
public:
  Analysis(const Function& f, const std::vector<std::optional<Range>>& entry)
      : f_(f), cfg_(buildCfg(f)), ranges_(f.insts.size(), kEmpty),
        growths_(f.insts.size(), 0) {
    findEntryLoads(entry);
  }

  std::vector<Range> run();
  std::vector<bool> reachable() const;

private:
  void findEntryLoads(const std::vector<std::optional<Range>>& entry);
  void numberDominatorTree();

  bool dominates(BlockId a, BlockId b) const {
    return pre_[a] <= pre_[b] && post_[b] <= post_[a];
  }

  void collectConstraints();
  template <typename Each>
  void comparisons(ValueId cond, bool sense, Each each) const;
  Range bound(RelOp op, ValueId other) const;
  Range operand(ValueId v, BlockId use) const;
  Range phiInput(ValueId v, BlockId pred, BlockId phiBlock) const;
  Range transfer(ValueId id, const Inst& inst) const;
  bool sweep(bool narrowing);

  const Function& f_;
  Cfg cfg_;
  std::vector<std::uint32_t> pre_, post_;
  std::unordered_map<ValueId, std::vector<Constraint>> constraints_;
  std::vector<Range> ranges_;
  std::vector<int> growths_;
  std::unordered_map<ValueId, Range> entryLoads_;
};

// The loads of a local that nothing may have written yet on any path from
// the entry read its value at the start. A store writes its local; an
// indirect store, and a block that may call a subprogram (which shares the
// locals), may write any.
void Analysis::findEntryLoads(const std::vector<std::optional<Range>>& entry) {
  if (entry.empty() || f_.blocks.empty()) {
    return;
  }
  using Written = std::bitset<kLocalCount>;
  const auto write = [&](const Inst& inst, Written& w) {
    if (inst.op == Op::StVar) {
      const std::int64_t n = varNumberOf(inst);
      if (n >= 1 && n <= kLocalCount) {
        w.set(static_cast<std::size_t>(n - 1));
      }
    } else if (inst.op == Op::StInd ||
               (inst.op == Op::Nc && ncMayShareFrame(f_, inst))) {
      w.set();
    }
  };
  std::vector<Written> out(f_.blocks.size());
  const auto in = [&](BlockId b) {
    Written w;
    for (BlockId p : cfg_.preds[b]) {
      w |= out[p];
    }
    return w;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (BlockId b : cfg_.rpo) {
      Written w = in(b);
      for (ValueId id : f_.blocks[b].insts) {
        write(f_.insts[id], w);
      }
      if (w != out[b]) {
        out[b] = w;
        changed = true;
      }
    }
  }
  for (BlockId b : cfg_.rpo) {
    Written w = in(b);
    for (ValueId id : f_.blocks[b].insts) {
      const Inst& inst = f_.insts[id];
      const std::int64_t n = inst.op == Op::LdVar ? varNumberOf(inst) : 0;
      if (n >= 1 && n <= static_cast<std::int64_t>(entry.size()) &&
          !w.test(static_cast<std::size_t>(n - 1)) &&
          entry[static_cast<std::size_t>(n - 1)]) {
        entryLoads_.emplace(id, *entry[static_cast<std::size_t>(n - 1)]);
      }
      write(inst, w);
    }
  }
}

// A block no run reaches: a condition that dominates it cannot hold, or
// every way in comes from such blocks.
std::vector<bool> Analysis::reachable() const {
  const std::size_t n = f_.blocks.size();
  // Marked where the edge of a condition that cannot hold enters, then
  // down the dominator tree: reverse post-order visits a block's
  // immediate dominator before it.
  std::vector<bool> dead(n, false);
  for (const auto& [value, list] : constraints_) {
    for (const Constraint& c : list) {
      dead[c.block] = dead[c.block] ||
                      (!isEmpty(ranges_[c.other]) &&
                       isEmpty(meet(ranges_[value], bound(c.op, c.other))));
    }
  }
  for (BlockId b : cfg_.rpo) {
    dead[b] = dead[b] || (b != 0 && dead[cfg_.idom[b]]);
  }
  std::vector<bool> reach(n, false);
  std::vector<BlockId> work;
  if (!cfg_.rpo.empty()) {
    reach[0] = true;
    work.push_back(0);
  }
  while (!work.empty()) {
    const BlockId b = work.back();
    work.pop_back();
    for (BlockId s : cfg_.succs[b]) {
      if (!reach[s] && !dead[s]) {
        reach[s] = true;
        work.push_back(s);
      }
    }
  }
  return reach;
}

// Pre- and post-order numbers of the dominator tree, for O(1) dominance.
void Analysis::numberDominatorTree() {
  std::size_t n = f_.blocks.size();
  std::vector<std::vector<BlockId>> children(n);
  for (BlockId b : cfg_.rpo) {
    if (b != 0) {
      children[cfg_.idom[b]].push_back(b);
    }
  }
  pre_.assign(n, 0);
  post_.assign(n, 0);
  std::uint32_t counter = 0;
  std::vector<std::pair<BlockId, std::size_t>> stack;
  if (!cfg_.rpo.empty()) {
    stack.emplace_back(0, 0);
    pre_[0] = counter++;
  }
  while (!stack.empty()) {
    auto& [b, next] = stack.back();
    if (next < children[b].size()) {
      BlockId c = children[b][next++];
      pre_[c] = counter++;
      stack.emplace_back(c, 0);
      continue;
    }
    post_[b] = counter++;
    stack.pop_back();
  }
}

// Calls each(value, op, other) for every comparison `value op other` that
// holds when `cond` has truth `sense`: through AND when true and OR when
// false, each comparison seen from both of its operands, and from the
// operand of a tonum (which has the same number).
template <typename Each>
void Analysis::comparisons(ValueId cond, bool sense, Each each) const {
  std::vector<std::pair<ValueId, bool>> work{{cond, sense}};
  while (!work.empty()) {
    auto [c, holds] = work.back();
    work.pop_back();
    const Inst& inst = f_.insts[c];
    if ((inst.op == Op::LogAnd && holds) || (inst.op == Op::LogOr && !holds)) {
      work.emplace_back(inst.ops[0], holds);
      work.emplace_back(inst.ops[1], holds);
      continue;
    }
    const std::optional<RelOp> rel = relationOf(inst.op);
    if (!rel) {
      continue;
    }
    const RelOp op = holds ? *rel : negated(*rel);
    if (op == RelOp::Ne) {
      continue;
    }
    auto side = [&](ValueId v, RelOp o, ValueId other) {
      each(v, o, other);
      if (f_.insts[v].op == Op::ToNum) {
        each(f_.insts[v].ops[0], o, other);
      }
    };
    side(inst.ops[0], op, inst.ops[1]);
    side(inst.ops[1], mirrored(op), inst.ops[0]);
  }
}

// A block entered only from a condbr (its single reachable predecessor) is
// guarded by the condition's truth on that edge.
void Analysis::collectConstraints() {
  for (BlockId b : cfg_.rpo) {
    const Inst& term = f_.insts[f_.blocks[b].insts.back()];
    if (term.op != Op::CondBr || term.targets[0] == term.targets[1]) {
      continue;
    }
    for (int t = 0; t < 2; ++t) {
      BlockId s = term.targets[t];
      // The only way in that a run can take (a block no path from the
      // entry reaches never runs).
      if (std::count_if(cfg_.preds[s].begin(), cfg_.preds[s].end(),
                        [&](BlockId p) { return cfg_.reachable(p); }) != 1) {
        continue;
      }
      comparisons(term.ops[0], t == 0, [&](ValueId v, RelOp op, ValueId other) {
        constraints_[v].push_back(Constraint{s, op, other});
      });
    }
  }
}

// What `value op other` says about value.
Range Analysis::bound(RelOp op, ValueId other) const {
  const Range& o = ranges_[other];
  if (isEmpty(o)) {
    return Range{}; // not computed yet: no information
  }
  // A double below (above) a bound is at most the double next to it.
  switch (op) {
    case RelOp::Lt:
      return Range{-kInf, std::nextafter(o.hi, -kInf)};
    case RelOp::Le:
      return Range{-kInf, o.hi};
    case RelOp::Gt:
      return Range{std::nextafter(o.lo, kInf), kInf};
    case RelOp::Ge:
      return Range{o.lo, kInf};
    case RelOp::Eq:
    case RelOp::Ne: // comparisons() never gives ne
      break;
  }
  return o;
}

Range Analysis::operand(ValueId v, BlockId use) const {
  Range r = ranges_[v];
  auto it = constraints_.find(v);
  if (it != constraints_.end()) {
    for (const Constraint& c : it->second) {
      if (dominates(c.block, use)) {
        r = meet(r, bound(c.op, c.other));
      }
    }
  }
  return r;
}

// The value as it leaves `pred` for `phiBlock`: also refined by the
// condition of that edge.
Range Analysis::phiInput(ValueId v, BlockId pred, BlockId phiBlock) const {
  Range r = operand(v, pred);
  const Inst& term = f_.insts[f_.blocks[pred].insts.back()];
  if (term.op == Op::CondBr && term.targets[0] != term.targets[1]) {
    comparisons(term.ops[0], term.targets[0] == phiBlock,
                [&](ValueId w, RelOp op, ValueId other) {
                  if (w == v) {
                    r = meet(r, bound(op, other));
                  }
                });
  }
  return r;
}

Range Analysis::transfer(ValueId id, const Inst& inst) const {
  if (inst.op == Op::Phi) {
    Range r = kEmpty;
    for (std::size_t i = 0; i < inst.ops.size(); ++i) {
      r = join(r, phiInput(inst.ops[i], inst.targets[i], inst.block));
    }
    return r;
  }
  if (inst.op == Op::Const) {
    const double v = inst.get<Number>().value;
    return Range{v, v};
  }
  if (inst.op == Op::Vacant) {
    return Range{0, 0};
  }
  if (inst.op == Op::LdVar) {
    const auto known = entryLoads_.find(id);
    return known == entryLoads_.end() ? Range{} : known->second;
  }
  Range a = inst.ops.empty() ? Range{} : operand(inst.ops[0], inst.block);
  Range b = inst.ops.size() < 2 ? Range{} : operand(inst.ops[1], inst.block);
  if (isEmpty(a) || isEmpty(b)) {
    return kEmpty; // on a path that cannot run
  }
  if (inst.op == Op::ToNum) {
    return a;
  }
  if (inst.op == Op::Neg) {
    return Range{-a.hi, -a.lo};
  }
  if (inst.op == Op::Fn) {
    return inst.ops.size() == 1 ? builtin(inst.get<BuiltinFn>().fn, a)
                                : Range{};
  }
  const std::optional<BinOp> bin = binaryOf(inst.op);
  if (!bin) {
    return Range{};
  }
  switch (*bin) {
    case BinOp::Add:
      return checked(a.lo + b.lo, a.hi + b.hi);
    case BinOp::Sub:
      return checked(a.lo - b.hi, a.hi - b.lo);
    case BinOp::Mul:
      return multiply(a, b);
    case BinOp::Div:
      return divide(a, b);
    case BinOp::Mod:
    case BinOp::And:
    case BinOp::Or:
    case BinOp::Xor:
      break;
  }
  return Range{};
}

// One pass over the blocks in reverse post-order; true if a range changed.
bool Analysis::sweep(bool narrowing) {
  bool changed = false;
  for (BlockId b : cfg_.rpo) {
    for (ValueId id : f_.blocks[b].insts) {
      const Inst& inst = f_.insts[id];
      Range now = transfer(id, inst);
      Range& old = ranges_[id];
      if (inst.op == Op::Phi && !isEmpty(old)) {
        if (narrowing) {
          now = Range{old.lo == -kInf ? now.lo : old.lo,
                      old.hi == kInf ? now.hi : old.hi};
        } else {
          now = join(old, now);
          if (now != old && ++growths_[id] > kGrowthsBeforeWidening) {
            now = Range{now.lo < old.lo ? -kInf : old.lo,
                        now.hi > old.hi ? kInf : old.hi};
          }
        }
      }
      if (now != old) {
        old = now;
        changed = true;
      }
    }
  }
  return changed;
}

std::vector<Range> Analysis::run() {
  numberDominatorTree();
  collectConstraints();
  int round = 0;
  while (sweep(false)) {
    if (++round == kMaxRounds) {
      return std::vector<Range>(f_.insts.size(), Range{});
    }
  }
  for (int i = 0; i < kNarrowingRounds; ++i) {
    sweep(true);
  }
  return ranges_;
}

} // namespace

std::vector<Range> valueRanges(const Function& f) {
  return analyseRanges(f, {}).values;
}

RangeFacts analyseRanges(const Function& f,
                         const std::vector<std::optional<Range>>& entry) {
  if (f.blocks.empty()) {
    return {std::vector<Range>(f.insts.size(), Range{}), {}};
  }
  Analysis analysis(f, entry);
  RangeFacts facts;
  facts.values = analysis.run();
  facts.reachable = analysis.reachable();
  return facts;
}

} // namespace mbc::ir
