// Where the tool goes (see reach_box.h): a forward analysis of abstract
// machine states over each function's blocks, to a fixed point over the
// calls. Positions are the control point's machine coordinates as the
// program places it (cutter compensation's offset is added to what a move
// reaches, not to where it ends), in the profile's unit (mm, or degrees).
#include "toolchain/reach_box.h"

#include <mbc/calling_codes.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <tuple>

namespace mbc::toolchain {

namespace {

using ir::Range;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// A block whose start grows more often than this is widened: what still
/// grows has no bound.
constexpr int kWidenAfter = 3;
/// The H numbers of a computed H tried one by one, at most.
constexpr double kMaxOffsetsTried = 1000;

Range join(const Range& a, const Range& b) {
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

Range plus(const Range& a, const Range& b) {
  return {a.lo + b.lo, a.hi + b.hi};
}

Range minus(const Range& a, const Range& b) {
  return {a.lo - b.hi, a.hi - b.lo};
}

Range times(const Range& a, const Range& b) {
  const double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  if (std::any_of(std::begin(p), std::end(p),
                  [](double v) { return std::isnan(v); })) {
    return {-kInfinity, kInfinity};
  }
  return {*std::min_element(std::begin(p), std::end(p)),
          *std::max_element(std::begin(p), std::end(p))};
}

Range widened(const Range& was, const Range& now) {
  return {now.lo < was.lo ? -kInfinity : now.lo,
          now.hi > was.hi ? kInfinity : now.hi};
}

enum : unsigned { kAbsolute = 1, kIncremental = 2 };

enum : unsigned { kStraight = 1, kCircular = 2 };

enum : unsigned { kNoLength = 1, kG43 = 2, kG44 = 4 };

/// The G17, G18 and G19 planes: their two axes.
constexpr char kPlaneAxes[3][2] = {{'X', 'Y'}, {'Z', 'X'}, {'Y', 'Z'}};
/// Each plane's arc centre letters, for its two axes.
constexpr char kCentreLetters[3][2] = {{'I', 'J'}, {'K', 'I'}, {'J', 'K'}};

/// Where the analysis stopped following the tool, and why.
struct Lost {
  std::string function;
  std::uint32_t line = 0;
  std::string why;

  bool operator==(const Lost&) const = default;
};

/// What a run may be in at a point of the program: each field holds every
/// value it may have (bits of the modal codes, ranges of numbers).
struct State {
  bool reached = false;
  std::optional<Lost> lost;
  unsigned distance = kAbsolute;
  unsigned motion = kStraight;
  unsigned planes = 1;                   // bit 0 G17, 1 G18, 2 G19
  unsigned systems = 1 << 1;             // bit n: the nth of G54-G59
  unsigned lengthModes = kNoLength;      // G49, G43, G44
  Range length{0, 0};                    // on the length axis, as it acts
  bool compensating = false;             // G41/G42
  bool cycle = false;                    // G73-G89
  Range cycleR{0, 0}, cycleBottom{0, 0}; // the hole's levels, machine
  std::vector<Range> position;

  bool operator==(const State&) const = default;
};

/// What a block's moves may do: per axis the range they may take it
/// through and the range it may start from, and the axes they move.
struct Move {
  std::vector<Range> reach;
  std::vector<Range> start;
  std::uint32_t moved = 0;
};

State joined(const State& a, const State& b) {
  if (!a.reached) {
    return b;
  }
  if (!b.reached) {
    return a;
  }
  State s = a;
  s.lost = a.lost ? a.lost : b.lost;
  s.distance |= b.distance;
  s.motion |= b.motion;
  s.planes |= b.planes;
  s.systems |= b.systems;
  s.lengthModes |= b.lengthModes;
  s.length = join(a.length, b.length);
  s.compensating = a.compensating || b.compensating;
  if (a.cycle && b.cycle) {
    s.cycleR = join(a.cycleR, b.cycleR);
    s.cycleBottom = join(a.cycleBottom, b.cycleBottom);
  } else if (b.cycle) {
    s.cycleR = b.cycleR;
    s.cycleBottom = b.cycleBottom;
  }
  s.cycle = a.cycle || b.cycle;
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    s.position[i] = join(a.position[i], b.position[i]);
  }
  return s;
}

/// `now` (which holds `was`) with every range that grew unbounded.
State widenedState(const State& was, State now) {
  if (!was.reached) {
    return now;
  }
  now.length = widened(was.length, now.length);
  now.cycleR = widened(was.cycleR, now.cycleR);
  now.cycleBottom = widened(was.cycleBottom, now.cycleBottom);
  for (std::size_t i = 0; i < now.position.size(); ++i) {
    now.position[i] = widened(was.position[i], now.position[i]);
  }
  return now;
}

/// An address word of a block: its value's range in the program's unit
/// (a literal without decimal point in least increments), and whether it
/// may be left out (a bare variable that is vacant).
struct Word {
  char letter;
  Range value;
  Range count; // unscaled: K and L of a cycle count holes
  std::optional<double> constant;
  bool optional;
};

/// One block's words, by letter.
struct BlockWords {
  std::vector<Word> words;
  std::vector<double> gCodes;
  bool computedG = false;

  const Word* word(char letter) const {
    for (const Word& w : words) {
      if (w.letter == letter) {
        return &w;
      }
    }
    return nullptr;
  }

  bool has(double g) const {
    return std::find(gCodes.begin(), gCodes.end(), g) != gCodes.end();
  }
};

/// The G codes that change nothing the analysis follows.
bool harmless(double g) {
  static const std::set<double> kCodes = {9,  11, 15, 21, 50, 50.1, 61,
                                          62, 63, 64, 67, 69, 93,   94,
                                          95, 96, 97, 98, 99};
  return kCodes.count(g) != 0;
}

bool cycleCode(double g) {
  return g == 73 || g == 74 || g == 76 ||
         (g >= 81 && g <= 89 && g == std::floor(g));
}

class Analysis {
public:
  Analysis(const UnitRanges& unit, const MachineFacts& machine)
      : unit_(unit), machine_(machine) {
    const std::size_t axes = machine.axes.size();
    box_.assign(axes, Range{kInfinity, -kInfinity});
    lengthAxis_ = machine.axisOf('Z');
  }

  void run() {
    State start;
    start.reached = true;
    for (double p : machine_.position) {
      start.position.push_back({p, p});
    }
    const ir::Function& main = unit_.main();
    if (machine_.lathe) {
      start.lost = Lost{main.name, firstLine(main),
                        "the analysis follows mills only (a lathe's "
                        "diameters and cycles are not)"};
    } else if (machine_.inch) {
      start.lost = Lost{main.name, firstLine(main),
                        "the analysis follows metric machines only"};
    } else if (machine_.lengthOnPlaneNormal) {
      start.lost = Lost{main.name, firstLine(main),
                        "the tool length offset is on the plane's normal "
                        "(5001#1 TLB)"};
    } else if (machine_.codeCalls && codeCalledProgramIn()) {
      start.lost = Lost{main.name, firstLine(main),
                        "the profile makes codes call programs O9000-O9029"};
    }
    enter(main, start);
    while (!work_.empty()) {
      const ir::Function* f = *work_.begin();
      work_.erase(work_.begin());
      analyse(*f);
    }
  }

  /// Per block (function, line), what its moves may do.
  const std::map<std::pair<std::string, std::uint32_t>, Move>& moves() const {
    return moves_;
  }

  /// Where the analysis lost the tool before a move.
  const std::set<std::tuple<std::string, std::uint32_t, std::string>>&
  losses() const {
    return losses_;
  }

  const std::vector<Range>& box() const { return box_; }

private:
  static std::uint32_t firstLine(const ir::Function& f) {
    for (const ir::Inst& inst : f.insts) {
      if (inst.line != 0) {
        return inst.line;
      }
    }
    return 0;
  }

  bool codeCalledProgramIn() const {
    const auto& functions = unit_.module().functions;
    return std::any_of(
        functions.begin(), functions.end(),
        [](const ir::Function& f) { return codeMayCallProgram(f.number); });
  }

  void enter(const ir::Function& f, const State& state) {
    State& entry = entries_[&f];
    const State next = joined(entry, state);
    if (next != entry) {
      entry = next;
      work_.insert(&f);
    }
  }

  /// What a call returns to: the state its program ends in.
  State call(const ir::Function& caller, const ir::Function* callee,
             const State& state, bool repeats, std::uint32_t line) {
    if (callee == nullptr) {
      return lose(state, caller, line,
                  "a call of a program the input does not have");
    }
    callers_[callee].insert(&caller);
    enter(*callee, state);
    const State& end = exits_[callee];
    if (repeats && end.reached) {
      enter(*callee, end); // the next round starts where one ended
    }
    return end;
  }

  static State lose(State state, const ir::Function& f, std::uint32_t line,
                    std::string why) {
    if (!state.lost) {
      state.lost = Lost{f.name, line, std::move(why)};
    }
    return state;
  }

  void analyse(const ir::Function& f) {
    const ir::RangeFacts* facts = unit_.facts(f);
    if (facts == nullptr) {
      return; // no run enters it
    }
    std::vector<State> in(f.blocks.size());
    std::vector<int> visits(f.blocks.size());
    in[0] = entries_[&f];
    std::set<ir::BlockId> queue{0};
    while (!queue.empty()) {
      const ir::BlockId b = *queue.begin();
      queue.erase(queue.begin());
      State state = in[b];
      for (ir::ValueId id : f.blocks[b].insts) {
        const ir::Inst& inst = f.insts[id];
        state = step(f, inst, facts->values, state);
        if (!state.reached) {
          break;
        }
        if (inst.op == ir::Op::Ret) {
          State& exit = exits_[&f];
          const State next = joined(exit, state);
          if (next != exit) {
            exit = next;
            for (const ir::Function* caller : callers_[&f]) {
              work_.insert(caller);
            }
          }
        }
        if (inst.op == ir::Op::Ret || inst.op == ir::Op::Raise ||
            inst.op == ir::Op::Unreachable) {
          break;
        }
        if (!(ir::opInfo(inst.op).flags & ir::Terminator)) {
          continue;
        }
        for (ir::BlockId target : inst.targets) {
          if (!facts->reachable[target]) {
            continue;
          }
          State next = joined(in[target], state);
          if (++visits[target] > kWidenAfter) {
            next = widenedState(in[target], next);
          }
          if (next != in[target]) {
            in[target] = std::move(next);
            queue.insert(target);
          }
        }
      }
    }
  }

  State step(const ir::Function& f, const ir::Inst& inst,
             const std::vector<Range>& values, State state) {
    switch (inst.op) {
      case ir::Op::Nc:
        return block(f, inst, values, std::move(state));
      case ir::Op::CallMacro: {
        const ir::Inst& p = f.insts[inst.ops[0]];
        if (p.op != ir::Op::Const) {
          return lose(state, f, inst.line, "a G65 with a computed P");
        }
        const Range l = values[inst.ops[1]];
        return call(f, unit_.called(p.get<ir::Number>().value), state, l.hi > 1,
                    inst.line);
      }
      case ir::Op::StVar:
        return writesMachineData(
                   Range{static_cast<double>(inst.get<ir::VarNumber>().number),
                         static_cast<double>(inst.get<ir::VarNumber>().number)})
                   ? lose(state, f, inst.line,
                          fmt::format("#{} is written at run time",
                                      inst.get<ir::VarNumber>().number))
                   : state;
      case ir::Op::StInd:
        return writesMachineData(values[inst.ops[0]])
                   ? lose(state, f, inst.line,
                          "a #[...] written at run time may be an offset")
                   : state;
      default:
        return state;
    }
  }

  /// The work and tool offsets and the parameters: data the analysis reads
  /// from the profile, which a write at run time changes.
  static bool writesMachineData(const Range& number) {
    const auto meets = [&](double lo, double hi) {
      return number.hi >= lo && number.lo <= hi;
    };
    return meets(2001, 2999) || meets(5201, 5999) || meets(7001, 7999) ||
           meets(10001, 19999);
  }

  BlockWords wordsOf(const ir::Function& f, const ir::Inst& nc,
                     const std::vector<Range>& values) const {
    BlockWords out;
    const auto& words = nc.get<ir::Words>().words;
    for (std::size_t i = 0; i < words.size(); ++i) {
      const ir::Inst& operand = f.insts[nc.ops[i]];
      // A bare variable that is vacant drops its word; the ranges read
      // vacant as 0, so one whose range has no 0 is never vacant.
      const Range value = values[nc.ops[i]];
      Word w{words[i].letter, value, value, std::nullopt,
             (words[i].kind == ir::WordKind::Var ||
              words[i].kind == ir::WordKind::NegVar) &&
                 value.lo <= 0 && value.hi >= 0};
      if (operand.op == ir::Op::Const) {
        w.constant = operand.get<ir::Number>().value;
      }
      if (words[i].kind == ir::WordKind::NegVar) {
        w.value = {-w.value.hi, -w.value.lo};
      }
      // X10 is 0.010 mm, unless 3401#0 DPI.
      if (words[i].kind == ir::WordKind::Int && !machine_.decimalPointInput &&
          std::string_view("XYZABCUVWIJKR").find(w.letter) !=
              std::string_view::npos) {
        w.value = {w.value.lo / 1000, w.value.hi / 1000};
        if (w.constant) {
          *w.constant /= 1000;
        }
      }
      if (w.letter == 'G') {
        if (w.constant) {
          out.gCodes.push_back(*w.constant);
        } else {
          out.computedG = true;
        }
      }
      out.words.push_back(w);
    }
    return out;
  }

  /// The machine coordinate of program coordinate `value` on `axis`.
  Range placed(const State& s, int axis, const Range& value) const {
    Range origin{kInfinity, -kInfinity};
    for (std::size_t set = 1; set < machine_.workOffsets.size(); ++set) {
      if ((s.systems >> set & 1) != 0) {
        const double o =
            machine_.workOffsets[set][static_cast<std::size_t>(axis)];
        origin = join(origin, Range{o, o});
      }
    }
    Range at = plus(origin, value);
    return axis == lengthAxis_ ? plus(at, s.length) : at;
  }

  /// Where a word sends its axis: absolute, incremental or either.
  Range target(const State& s, int axis, const Word& w) const {
    const Range from = s.position[static_cast<std::size_t>(axis)];
    Range to{kInfinity, -kInfinity};
    if (s.distance & kAbsolute) {
      to = join(to, placed(s, axis, w.value));
    }
    if (s.distance & kIncremental) {
      to = join(to, plus(from, w.value));
    }
    return w.optional ? join(to, from) : to;
  }

  /// The tool length offset a block puts in force.
  std::optional<Range> lengthOf(const State& s, const BlockWords& words,
                                unsigned modes) const {
    const Word* h = words.word('H');
    if (h == nullptr || modes == kNoLength) {
      return modes == kNoLength ? std::optional(Range{0, 0}) : s.length;
    }
    const Range numbers = h->value;
    if (!std::isfinite(numbers.lo) || !std::isfinite(numbers.hi) ||
        numbers.hi - numbers.lo > kMaxOffsetsTried) {
      return std::nullopt;
    }
    Range length{kInfinity, -kInfinity};
    for (double n = std::round(numbers.lo); n <= std::round(numbers.hi); ++n) {
      const auto i = static_cast<std::size_t>(std::max(n, 0.0));
      const double value =
          i < machine_.lengths.size() ? machine_.lengths[i] : 0;
      if (modes & kG43) {
        length = join(length, Range{value, value});
      }
      if (modes & kG44) {
        length = join(length, Range{-value, -value});
      }
    }
    if (h->optional) {
      length = join(length, s.length);
    }
    if (modes & kNoLength) {
      length = join(length, Range{0, 0}); // H alone sets no offset in G49
    }
    return length;
  }

  State block(const ir::Function& f, const ir::Inst& nc,
              const std::vector<Range>& values, State s) {
    const std::uint32_t line = nc.line;
    if (s.lost) {
      return moveInLostState(f, nc, values, s);
    }
    const BlockWords words = wordsOf(f, nc, values);
    if (words.computedG) {
      return lose(s, f, line, "a G code computed at run time");
    }
    enum class Shot { None, Dwell, Reference, Machine, Skip };
    Shot shot = Shot::None;
    double reference = 0; // G28: 0; G30: P2-P4
    bool cycleBlock = false;
    for (double g : words.gCodes) {
      if (g == 0 || g == 1) {
        s.motion = kStraight;
        s.cycle = false;
      } else if (g == 2 || g == 3) {
        s.motion = kCircular;
        s.cycle = false;
      } else if (g == 17 || g == 18 || g == 19) {
        s.planes = 1U << static_cast<int>(g - 17);
      } else if (g == 90 || g == 91) {
        s.distance = g == 90 ? kAbsolute : kIncremental;
      } else if (g >= 54 && g <= 59 && g == std::floor(g)) {
        s.systems = 1U << static_cast<int>(g - 53);
      } else if (g == 43 || g == 44) {
        s.lengthModes = g == 43 ? kG43 : kG44;
      } else if (g == 49) {
        s.lengthModes = kNoLength;
      } else if (g == 41 || g == 42) {
        s.compensating = true;
      } else if (g == 40) {
        s.compensating = false;
      } else if (g == 80) {
        s.cycle = false;
      } else if (cycleCode(g)) {
        cycleBlock = true;
      } else if (g == 4) {
        shot = Shot::Dwell;
      } else if (g == 28 || g == 30) {
        shot = Shot::Reference;
        reference = g == 28 ? 0 : 2;
      } else if (g == 53) {
        shot = Shot::Machine;
      } else if (g == 31) {
        shot = Shot::Skip;
      } else if (!harmless(g)) {
        return lose(s, f, line,
                    fmt::format("G{}, which the analysis does not follow", g));
      }
    }
    if (s.cycle && words.has(40)) {
      s.compensating = false;
    }
    // The tool length offset in force from this block.
    const Range oldLength = s.length;
    const std::optional<Range> length = lengthOf(s, words, s.lengthModes);
    if (!length) {
      return lose(s, f, line, "an H the analysis cannot bound");
    }
    s.length = *length;
    // Where the moves may take each axis, from the start on (the start
    // itself is the last block's).
    std::vector<Range> reach(s.position.size(), Range{kInfinity, -kInfinity});
    std::vector<Range> end = s.position;
    const int lz = lengthAxis_;
    // The axes the block moves: the others stay where they are, within or
    // not.
    std::uint32_t moved = 0;
    const auto mark = [&](int axis) {
      moved |= axis >= 0 ? std::uint32_t{1} << axis : 0;
    };
    if (lz >= 0 && s.length != oldLength && shot == Shot::None) {
      // A change of the offset moves the control point by the difference.
      const auto z = static_cast<std::size_t>(lz);
      end[z] = plus(end[z], minus(s.length, oldLength));
      mark(lz);
    }
    if (shot == Shot::Dwell) {
      return calls(f, nc, words, std::move(s));
    }
    if (shot == Shot::Reference) {
      if (const Word* p = words.word('P'); p != nullptr) {
        if (!p->constant || *p->constant < 2 || *p->constant > 4) {
          return lose(s, f, line, "a G30 P the analysis cannot tell");
        }
        reference = *p->constant;
      }
    }
    if (shot == Shot::Machine && (s.distance & kIncremental)) {
      return lose(s, f, line, "G53 where G91 may be in force");
    }
    bool planeWords = false;
    for (const Word& w : words.words) {
      const int axis = machine_.axisOf(w.letter);
      if (axis < 0) {
        continue;
      }
      const auto i = static_cast<std::size_t>(axis);
      mark(axis);
      planeWords = true;
      switch (shot) {
        case Shot::Machine:
          end[i] = w.optional ? join(w.value, s.position[i]) : w.value;
          break;
        case Shot::Reference: {
          // Through the point the word gives, to the reference position.
          const Range through = target(s, axis, w);
          reach[i] = join(reach[i], through);
          const double at =
              reference == 0
                  ? 0
                  : machine_
                        .references[static_cast<std::size_t>(reference) - 2][i];
          end[i] =
              w.optional ? join(Range{at, at}, s.position[i]) : Range{at, at};
          break;
        }
        default:
          end[i] = target(s, axis, w);
          if (lz >= 0 && axis == lz && s.length != oldLength &&
              (s.distance & kIncremental)) {
            end[i] = join(end[i], plus(end[i], minus(s.length, oldLength)));
          }
          break;
      }
    }
    if (cycleBlock || (s.cycle && planeWords && shot == Shot::None)) {
      if (!cycleHole(words, s)) {
        return lose(s, f, line,
                    "a canned cycle the analysis does not follow (outside "
                    "G17, or without Z)");
      }
      repeatHoles(words, s, end);
      const auto z = static_cast<std::size_t>(lz);
      reach[z] = join(reach[z], join(s.cycleR, s.cycleBottom));
      // Back to the initial level (G98) or the R point (G99).
      end[z] = join(s.position[z], s.cycleR);
      mark(lz);
    }
    for (std::size_t i = 0; i < end.size(); ++i) {
      reach[i] = join(reach[i], end[i]);
    }
    const bool arc =
        (s.motion & kCircular) != 0 && shot == Shot::None && !s.cycle &&
        std::any_of(words.words.begin(), words.words.end(), [](const Word& w) {
          return std::string_view("IJKR").find(w.letter) !=
                 std::string_view::npos;
        });
    if (arc) {
      // A full circle has no axis word.
      moved |= planeAxesOf(s.planes);
      arcReach(s, words, end, reach);
    }
    std::vector<Range> start = s.position;
    if (s.compensating && (moved & planeAxesOf(s.planes)) != 0) {
      // The tool centre stands off the programmed path by the offset, at
      // an outer corner by up to the square root of two of it: twice it
      // bounds both, on both axes of the plane, from where the tool stood.
      const double by = 2 * machine_.largestRadius;
      moved |= planeAxesOf(s.planes);
      for (std::size_t i = 0; i < reach.size(); ++i) {
        if ((planeAxesOf(s.planes) >> i & 1) != 0) {
          reach[i] = {reach[i].lo - by, reach[i].hi + by};
          start[i] = {start[i].lo - by, start[i].hi + by};
        }
      }
    }
    if (shot == Shot::Skip) {
      // G31 stops anywhere on its way.
      for (std::size_t i = 0; i < end.size(); ++i) {
        end[i] = join(end[i], s.position[i]);
      }
    }
    if (moved != 0) {
      record(f, line, Move{reach, start, moved});
    }
    s.position = std::move(end);
    return calls(f, nc, words, std::move(s));
  }

  /// A block's call by P (M98, and G65 written in an nc block), after its
  /// moves.
  State calls(const ir::Function& f, const ir::Inst& nc,
              const BlockWords& words, State s) {
    const CallByP byP = callByP(f, nc);
    if (!byP.calls) {
      return s;
    }
    if (!byP.constant) {
      return lose(s, f, nc.line, "a call with a computed P");
    }
    const Word* l = words.word('L');
    return call(f, unit_.called(*byP.constant), s,
                l != nullptr && l->value.hi > 1, nc.line);
  }

  /// The hole of a canned cycle (G17, along Z): the cycle's R point and
  /// bottom in machine coordinates, kept for the blocks after it.
  bool cycleHole(const BlockWords& words, State& s) const {
    const int lz = lengthAxis_;
    if (lz < 0 || s.planes != 1) {
      return false;
    }
    const auto z = static_cast<std::size_t>(lz);
    const Range initial = s.position[z];
    const Word* r = words.word('R');
    const Word* bottom = words.word('Z');
    const bool starts = !s.cycle;
    if (starts && bottom == nullptr) {
      return false;
    }
    if (r != nullptr) {
      Range level{kInfinity, -kInfinity};
      if (s.distance & kAbsolute) {
        level = join(level, placed(s, lz, r->value));
      }
      if (s.distance & kIncremental) {
        level = join(level, plus(initial, r->value));
      }
      s.cycleR = r->optional ? join(level, starts ? initial : s.cycleR) : level;
    } else if (starts) {
      s.cycleR = initial;
    }
    if (bottom != nullptr) {
      Range level{kInfinity, -kInfinity};
      if (s.distance & kAbsolute) {
        level = join(level, placed(s, lz, bottom->value));
      }
      if (s.distance & kIncremental) {
        level = join(level, plus(s.cycleR, bottom->value));
      }
      s.cycleBottom = bottom->optional ? join(level, s.cycleBottom) : level;
    }
    s.cycle = true;
    return true;
  }

  /// K (or L) holes: in G91 each one the block's X and Y further on.
  void repeatHoles(const BlockWords& words, const State& s,
                   std::vector<Range>& end) const {
    const Word* k = words.word('K');
    k = k != nullptr ? k : words.word('L');
    if (k == nullptr || k->count.hi <= 1 || !(s.distance & kIncremental)) {
      return;
    }
    const Range count{std::max(0.0, std::round(k->count.lo)),
                      std::round(k->count.hi)};
    for (const Word& w : words.words) {
      const int axis = machine_.axisOf(w.letter);
      if (axis < 0 || axis == lengthAxis_) {
        continue;
      }
      const auto i = static_cast<std::size_t>(axis);
      end[i] = join(end[i], plus(s.position[i], times(count, w.value)));
    }
  }

  /// An arc reaches at most a radius beyond its centre, which is a radius
  /// from its start and its end: with I, J, K the centre is known within
  /// their ranges; with R within 2 R of both ends.
  void arcReach(const State& s, const BlockWords& words,
                const std::vector<Range>& end,
                std::vector<Range>& reach) const {
    for (int plane = 0; plane < 3; ++plane) {
      if ((s.planes >> plane & 1) == 0) {
        continue;
      }
      const Word* c[2] = {words.word(kCentreLetters[plane][0]),
                          words.word(kCentreLetters[plane][1])};
      const Word* r = words.word('R');
      if (c[0] == nullptr && c[1] == nullptr && r == nullptr) {
        continue; // no arc: a straight move (3403#5 CIR off)
      }
      double radius = 0;
      if (c[0] != nullptr || c[1] != nullptr) {
        for (const Word* w : c) {
          if (w != nullptr) {
            const double most =
                std::max(std::fabs(w->value.lo), std::fabs(w->value.hi));
            radius += most * most;
          }
        }
        radius = std::sqrt(radius);
      }
      if (r != nullptr) {
        radius = std::max(
            radius, std::max(std::fabs(r->value.lo), std::fabs(r->value.hi)));
      }
      for (int k = 0; k < 2; ++k) {
        const int axis = machine_.axisOf(kPlaneAxes[plane][k]);
        if (axis < 0) {
          continue;
        }
        const auto i = static_cast<std::size_t>(axis);
        const Range& from = s.position[i];
        Range within{std::max(from.lo, end[i].lo) - 2 * radius,
                     std::min(from.hi, end[i].hi) + 2 * radius};
        if (c[k] != nullptr && r == nullptr) {
          const Range centre = plus(from, c[k]->value);
          within = {std::max(within.lo, centre.lo - radius),
                    std::min(within.hi, centre.hi + radius)};
        }
        reach[i] = join(reach[i], within);
      }
    }
  }

  /// A block met where the analysis has lost the tool: if it may move,
  /// the place it was lost at is where the analysis stops deciding.
  State moveInLostState(const ir::Function& f, const ir::Inst& nc,
                        const std::vector<Range>& values, State s) {
    const BlockWords words = wordsOf(f, nc, values);
    const bool moves =
        std::any_of(words.words.begin(), words.words.end(), [&](const Word& w) {
          return machine_.axisOf(w.letter) >= 0;
        });
    if (moves) {
      losses_.emplace(s.lost->function, s.lost->line, s.lost->why);
    }
    const CallByP byP = callByP(f, nc);
    if (byP.calls && byP.constant) {
      return call(f, unit_.called(*byP.constant), s, true, nc.line);
    }
    if (byP.calls) {
      // Whatever the computed P calls starts where the tool was lost.
      for (const ir::Function& g : unit_.module().functions) {
        enter(g, s);
      }
    }
    return s;
  }

  void record(const ir::Function& f, std::uint32_t line, const Move& move) {
    auto [it, added] = moves_.try_emplace({f.name, line}, move);
    if (!added) {
      Move& known = it->second;
      known.moved |= move.moved;
      for (std::size_t i = 0; i < move.reach.size(); ++i) {
        known.reach[i] = join(known.reach[i], move.reach[i]);
        known.start[i] = join(known.start[i], move.start[i]);
      }
    }
    for (std::size_t i = 0; i < move.reach.size(); ++i) {
      box_[i] = join(box_[i], join(move.reach[i], move.start[i]));
    }
  }

  /// The axes of the planes in `planes`, as bits.
  std::uint32_t planeAxesOf(unsigned planes) const {
    std::uint32_t mask = 0;
    for (int plane = 0; plane < 3; ++plane) {
      if ((planes >> plane & 1) != 0) {
        for (char letter : kPlaneAxes[plane]) {
          const int axis = machine_.axisOf(letter);
          mask |= axis >= 0 ? std::uint32_t{1} << axis : 0;
        }
      }
    }
    return mask;
  }

  const UnitRanges& unit_;
  const MachineFacts& machine_;
  int lengthAxis_ = -1;
  std::map<const ir::Function*, State> entries_;
  std::map<const ir::Function*, State> exits_;
  std::map<const ir::Function*, std::set<const ir::Function*>> callers_;
  std::set<const ir::Function*> work_;
  std::map<std::pair<std::string, std::uint32_t>, Move> moves_;
  std::set<std::tuple<std::string, std::uint32_t, std::string>> losses_;
  std::vector<Range> box_;
};

/// "X may reach -770.000 mm in machine coordinates", or that it has no
/// bound.
std::string reachText(char axis, double v, bool rotary) {
  return std::isfinite(v)
             ? fmt::format("{} may reach {:.3f} {} in machine coordinates",
                           axis, v, rotary ? "deg" : "mm")
             : fmt::format("{} may go farther than any bound the analysis "
                           "finds",
                           axis);
}

} // namespace

Reach checkReach(const CompiledUnit& cu, const UnitRanges& unit,
                 const MachineFacts& machine, DiagnosticEngine& diags) {
  Analysis analysis(unit, machine);
  analysis.run();
  Reach result;
  for (const auto& [function, line, why] : analysis.losses()) {
    diags.report(DiagKind::StrokeUndecided, blockAt(cu.unit, function, line),
                 why);
    ++result.findings;
    result.decided = false;
  }
  for (const auto& [where, move] : analysis.moves()) {
    bool found = false;
    const auto block = blockAt(cu.unit, where.first, where.second);
    for (std::size_t i = 0; i < move.reach.size(); ++i) {
      const std::optional<Stroke>& stroke = machine.strokes[i];
      if (!stroke || (move.moved >> i & 1) == 0) {
        continue;
      }
      const bool rotary = (machine.rotaryMask >> i & 1) != 0;
      const auto say = [&](double reach, char side, double end, int parameter) {
        diags.report(DiagKind::StrokeLimit, block,
                     reachText(machine.axes[i], reach, rotary), side,
                     fmt::format("{:.3f}", end), parameter);
        found = true;
      };
      // A tool beyond an end may come back, not go farther (as the run's
      // check has it).
      const Range& reach = move.reach[i];
      if (reach.hi > std::max(stroke->high, move.start[i].lo)) {
        say(reach.hi, '+', stroke->high, 1320);
      }
      if (reach.lo < std::min(stroke->low, move.start[i].hi)) {
        say(reach.lo, '-', stroke->low, 1321);
      }
    }
    result.findings += found ? 1 : 0;
  }
  result.box = analysis.box();
  return result;
}

} // namespace mbc::toolchain
