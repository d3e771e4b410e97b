// The IR verifier (see verifier.h). Each check reports and goes on, so one
// run lists every problem; checks that index by an id test its range first,
// because malformed IR is exactly what arrives here.
#include "ir/verifier.h"

#include "ir/cfg.h"
#include "ir/printer.h"
#include <mbc/arith.h>
#include <mbc/limits.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <set>

namespace mbc::ir {

namespace {

std::string_view typeName(Type t) {
  constexpr std::array<std::string_view, 5> kNames = {"no value", "num", "vnum",
                                                      "bool", "flow"};
  auto i = static_cast<std::size_t>(t);
  return i < kNames.size() ? kNames[i] : "?";
}

// The type operand i must have; VNum accepts Num too, None any value but a
// flow. Arithmetic, functions,
// ordering comparisons and variable numbers read a number (vacant as 0
// through an explicit tonum); equality, stores, NC words, print items and
// the computed GOTO tell vacant apart, so they take either.
Type operandType(const Inst& inst, std::size_t i) {
  switch (inst.op) {
    case Op::LogAnd:
    case Op::LogOr:
    case Op::LogXor:
    case Op::CondBr:
      return Type::Bool;
    case Op::Resume:
      return Type::Flow;
    case Op::Trace:
      return Type::None;
    case Op::Phi:
      return inst.type;
    case Op::StInd:
      return i == 0 ? Type::Num : Type::VNum;
    case Op::ToNum:
    case Op::Eq:
    case Op::Ne:
    case Op::StVar:
    case Op::Nc:
    case Op::CallMacro:
    case Op::Dprnt:
    case Op::Bprnt:
    case Op::Switch:
      return Type::VNum;
    default:
      return Type::Num;
  }
}

bool accepts(Type want, Type got) {
  if (want == Type::None) {
    return got != Type::Flow && got != Type::None;
  }
  return got == want || (want == Type::VNum && got == Type::Num);
}

// The holes of a trace template ("{}", "{#}", "{?}"; mbrt_trace_values).
std::size_t traceHoles(std::string_view tmpl) {
  std::size_t n = 0;
  for (std::string_view hole : {"{}", "{#}", "{?}"}) {
    for (auto at = tmpl.find(hole); at != std::string_view::npos;
         at = tmpl.find(hole, at + 1)) {
      ++n;
    }
  }
  return n;
}

// The number of block targets an instruction needs.
std::size_t expectedTargets(const Inst& inst) {
  switch (inst.op) {
    case Op::Br:
      return 1;
    case Op::CondBr:
      return 2;
    case Op::Switch:
      return inst.cases.size();
    case Op::Resume: // NEXT, then the M99 P landing or one per case
      return inst.cases.empty() && inst.targets.size() == 2
                 ? 2
                 : inst.cases.size() + 1;
    case Op::Phi:
      return inst.ops.size();
    default:
      return 0;
  }
}

bool isLetter(std::int64_t c) {
  return c >= 'A' && c <= 'Z';
}

class FunctionVerifier {
public:
  FunctionVerifier(const Module& m, const Function& f,
                   std::vector<std::string>& errors)
      : module_(m), f_(f), errors_(errors) {}

  void run();

private:
  struct Place {
    BlockId block = kNoBlock;
    std::uint32_t index = 0;
  };

  void fail(BlockId b, ValueId id, const std::string& message);
  void failBlock(BlockId b, const std::string& message);
  void placeInstructions();
  void checkBlock(BlockId b);
  void checkInst(BlockId b, std::uint32_t index, ValueId id);
  void checkOperandCount(BlockId b, ValueId id, const Inst& inst);
  void checkTargets(BlockId b, ValueId id, const Inst& inst);
  void checkCases(BlockId b, ValueId id, const Inst& inst);
  void checkWords(BlockId b, ValueId id, const Inst& inst, std::size_t from);
  void checkAttributes(BlockId b, ValueId id, const Inst& inst);
  void checkOperands(BlockId b, std::uint32_t index, ValueId id,
                     const Inst& inst);
  void checkDominance(BlockId b, std::uint32_t index, ValueId id,
                      const Inst& inst, std::size_t i);
  void checkPhiInputs(BlockId b, ValueId id, const Inst& inst);
  void checkLanding(BlockId b, ValueId id);

  const Module& module_;
  const Function& f_;
  std::vector<std::string>& errors_;
  std::vector<Place> place_; // where each instruction sits
  Cfg cfg_;
};

void FunctionVerifier::fail(BlockId b, ValueId id, const std::string& message) {
  errors_.push_back(fmt::format("@{} b{}: {}: {}", f_.name, b,
                                printInst(module_, f_, id), message));
}

void FunctionVerifier::failBlock(BlockId b, const std::string& message) {
  errors_.push_back(fmt::format("@{} b{}: {}", f_.name, b, message));
}

void FunctionVerifier::run() {
  if (f_.blocks.empty()) {
    errors_.push_back(fmt::format("@{}: function has no blocks", f_.name));
    return;
  }
  cfg_ = buildCfg(f_);
  placeInstructions();
  for (BlockId b = 0; b < f_.blocks.size(); ++b) {
    checkBlock(b);
  }
}

// Each instruction sits in at most one block, at one position, and knows
// its block.
void FunctionVerifier::placeInstructions() {
  place_.assign(f_.insts.size(), Place{});
  for (BlockId b = 0; b < f_.blocks.size(); ++b) {
    const std::vector<ValueId>& ids = f_.blocks[b].insts;
    for (std::uint32_t i = 0; i < ids.size(); ++i) {
      ValueId id = ids[i];
      if (id >= f_.insts.size()) {
        failBlock(b, fmt::format("lists %{}, which is not an instruction "
                                 "of the function",
                                 id));
      } else if (place_[id].block != kNoBlock) {
        fail(b, id,
             fmt::format("the instruction is also in b{}", place_[id].block));
      } else {
        place_[id] = Place{b, i};
        if (f_.insts[id].block != b) {
          fail(b, id,
               fmt::format("the instruction records block b{}",
                           f_.insts[id].block));
        }
      }
    }
  }
}

// One terminator, last; phis before everything else (as LLVM requires, so
// that codegen can map them one to one).
void FunctionVerifier::checkBlock(BlockId b) {
  const std::vector<ValueId>& ids = f_.blocks[b].insts;
  if (ids.empty()) {
    failBlock(b, "block is empty: it needs a terminator");
    return;
  }
  bool pastPhis = false;
  for (std::uint32_t i = 0; i < ids.size(); ++i) {
    ValueId id = ids[i];
    if (id >= f_.insts.size() || place_[id].block != b ||
        place_[id].index != i) {
      continue; // reported by placeInstructions
    }
    const Inst& inst = f_.insts[id];
    bool terminator = opInfo(inst.op).flags & Terminator;
    bool last = i + 1 == ids.size();
    if (terminator && !last) {
      fail(b, id, "terminator in the middle of the block");
    } else if (!terminator && last) {
      failBlock(b, "block does not end with a terminator");
    }
    if (inst.op == Op::Phi && pastPhis) {
      fail(b, id, "phi after a non-phi instruction");
    }
    pastPhis = pastPhis || inst.op != Op::Phi;
    checkInst(b, i, id);
  }
}

void FunctionVerifier::checkInst(BlockId b, std::uint32_t index, ValueId id) {
  const Inst& inst = f_.insts[id];
  Type defined = opInfo(inst.op).result;
  bool numPhi = inst.op == Op::Phi && inst.type == Type::Num;
  if (inst.type != defined && !numPhi) {
    fail(b, id,
         fmt::format("type is {}, but {} defines {}", typeName(inst.type),
                     opInfo(inst.op).mnemonic, typeName(defined)));
  }
  checkAttributes(b, id, inst);
  checkOperandCount(b, id, inst);
  checkTargets(b, id, inst);
  checkCases(b, id, inst);
  checkOperands(b, index, id, inst);
  if (inst.op == Op::Phi) {
    checkPhiInputs(b, id, inst);
  }
  if (inst.op == Op::RetSeq) {
    checkLanding(b, id);
  }
}

// retseq reads the sequence number of the M99 P that entered its block, so
// every way into the block must come from a resume's landing edge, maybe
// through blocks that only branch on (mem2ssa's landing pads).
void FunctionVerifier::checkLanding(BlockId b, ValueId id) {
  std::vector<bool> seen(f_.blocks.size(), false);
  std::vector<BlockId> work{b};
  while (!work.empty()) {
    BlockId into = work.back();
    work.pop_back();
    for (BlockId p : cfg_.preds[into]) {
      const std::vector<ValueId>& ids = f_.blocks[p].insts;
      const Inst* term = ids.empty() ? nullptr : &f_.insts[ids.back()];
      if (term != nullptr && term->op == Op::Resume && term->cases.empty() &&
          term->targets.size() == 2 && term->targets[1] == into &&
          term->targets[0] != into) {
        continue;
      }
      if (term != nullptr && term->op == Op::Br && p != b) {
        if (!seen[p]) {
          seen[p] = true;
          work.push_back(p);
        }
        continue;
      }
      fail(b, id,
           fmt::format("b{} enters b{} other than by an M99 P landing edge", p,
                       into));
    }
  }
}

void FunctionVerifier::checkOperandCount(BlockId b, ValueId id,
                                         const Inst& inst) {
  std::size_t n = inst.ops.size();
  auto expect = [&](std::size_t want, std::string_view why) {
    if (n != want) {
      fail(b, id,
           fmt::format("expected {} operand(s){}, got {}", want, why, n));
    }
  };
  switch (inst.op) {
    case Op::Fn:
      if (inst.attr >= 0 && inst.attr < builtinCount()) {
        auto fn = static_cast<Builtin>(inst.attr);
        auto arity = static_cast<std::size_t>(builtinArity(fn));
        expect(arity, fmt::format(" for {}", builtinMnemonic(fn)));
      }
      return;
    case Op::Phi: // one per input block: checkTargets
      return;
    case Op::Raise:
      expect(0, "");
      if (alarmInfo(static_cast<AlarmId>(inst.attr)).prefix[0] == '\0') {
        fail(b, id,
             fmt::format("raise of alarm {}, which has no code", inst.attr));
      }
      return;
    case Op::Trace:
      if (inst.str == 0) {
        fail(b, id, "trace without a template");
      } else if (inst.str <= module_.strings.size()) {
        expect(traceHoles(module_.strings[inst.str - 1]),
               " for the template's holes");
      }
      return;
    case Op::Nc:
    case Op::CallMacro:
      if (inst.op == Op::CallMacro && n < 2) {
        fail(b, id, "call.macro needs the operands P and L");
      } else if (inst.cases.size() != n) {
        fail(b, id,
             fmt::format("{} word descriptors for {} operands",
                         inst.cases.size(), n));
      }
      return;
    case Op::Dprnt:
    case Op::Bprnt:
      expect(static_cast<std::size_t>(std::count_if(
                 inst.cases.begin(), inst.cases.end(),
                 [](std::int64_t item) { return (item & 1) != 0; })),
             " for the value items");
      return;
    default:
      if (opInfo(inst.op).operands >= 0) {
        expect(static_cast<std::size_t>(opInfo(inst.op).operands), "");
      }
      return;
  }
}

void FunctionVerifier::checkTargets(BlockId b, ValueId id, const Inst& inst) {
  std::size_t want = expectedTargets(inst);
  if (inst.targets.size() != want) {
    fail(b, id,
         fmt::format("expected {} block target(s), got {}", want,
                     inst.targets.size()));
  }
  for (BlockId t : inst.targets) {
    if (t >= f_.blocks.size()) {
      fail(b, id, fmt::format("target b{} does not exist", t));
    }
  }
}

// Switch/resume case tables, word descriptors and print items.
void FunctionVerifier::checkCases(BlockId b, ValueId id, const Inst& inst) {
  switch (inst.op) {
    case Op::Switch:
    case Op::Resume: {
      std::set<std::int64_t> seen;
      for (std::int64_t n : inst.cases) {
        if (n < 1 || n > kMaxSequenceNumber) {
          fail(b, id,
               fmt::format("case {} is not a sequence number "
                           "(1..{})",
                           n, kMaxSequenceNumber));
        } else if (!seen.insert(n).second) {
          fail(b, id, fmt::format("case {} appears twice", n));
        }
      }
      return;
    }
    case Op::Nc:
      checkWords(b, id, inst, 0);
      return;
    case Op::CallMacro:
      checkWords(b, id, inst, 2); // cases[0], [1] (P, L) are placeholders
      return;
    case Op::Dprnt:
    case Op::Bprnt:
      for (std::int64_t item : inst.cases) {
        if (!(item & 1) &&
            (item < 0 || (item >> 1) >= std::ssize(module_.strings))) {
          fail(b, id, fmt::format("text item {} names no string", item >> 1));
        }
      }
      return;
    default:
      return;
  }
}

void FunctionVerifier::checkWords(BlockId b, ValueId id, const Inst& inst,
                                  std::size_t from) {
  for (std::size_t i = from; i < inst.cases.size(); ++i) {
    std::int64_t w = inst.cases[i];
    if (!isLetter(wordLetter(w)) || wordKind(w) > WordKind::NegVar ||
        (w >> 16) != 0) {
      fail(b, id, fmt::format("bad word descriptor {} for operand {}", w, i));
    }
  }
}

void FunctionVerifier::checkAttributes(BlockId b, ValueId id,
                                       const Inst& inst) {
  std::int64_t a = inst.attr;
  switch (inst.op) {
    case Op::Fn:
      if (a < 0 || a >= builtinCount()) {
        fail(b, id, fmt::format("unknown builtin {}", a));
      } else if (static_cast<Builtin>(a) == Builtin::Adp) {
        fail(b, id, "ADP is the adp operation, never fn");
      }
      break;
    case Op::RoundAddr:
      if (!isLetter(a)) {
        fail(b, id, fmt::format("address {} is not a letter A..Z", a));
      }
      break;
    case Op::BlockSkip:
      if (a < 1 || a > 9) {
        fail(b, id, "block skip switch outside 1..9");
      }
      break;
    case Op::LdVar:
    case Op::StVar:
      if (a < 0) {
        fail(b, id, "variable number is negative");
      }
      break;
    default:
      break;
  }
  if (inst.str > module_.strings.size()) {
    fail(b, id, fmt::format("message {} names no string", inst.str));
  }
}

void FunctionVerifier::checkOperands(BlockId b, std::uint32_t index, ValueId id,
                                     const Inst& inst) {
  for (std::size_t i = 0; i < inst.ops.size(); ++i) {
    ValueId v = inst.ops[i];
    if (v >= f_.insts.size() || place_[v].block == kNoBlock) {
      fail(b, id, fmt::format("operand %{} is not defined", v));
      continue;
    }
    Type got = f_.insts[v].type;
    Type want = operandType(inst, i);
    if (!accepts(want, got)) {
      fail(b, id,
           fmt::format("operand %{} is {}, expected {}", v, typeName(got),
                       want == Type::None ? "a value other than a flow"
                                          : typeName(want)));
    }
    checkDominance(b, index, id, inst, i);
  }
}

// A use must come after its definition on every path from b0; a phi input
// must be available at the end of its incoming block. Uses in unreachable
// blocks are not checked: dominance means nothing there.
void FunctionVerifier::checkDominance(BlockId b, std::uint32_t index,
                                      ValueId id, const Inst& inst,
                                      std::size_t i) {
  ValueId v = inst.ops[i];
  Place def = place_[v];
  if (inst.op == Op::Phi) {
    if (i < inst.targets.size() && cfg_.reachable(inst.targets[i]) &&
        !cfg_.dominates(def.block, inst.targets[i])) {
      fail(b, id,
           fmt::format("operand %{} does not dominate the end of b{}", v,
                       inst.targets[i]));
    }
    return;
  }
  if (!cfg_.reachable(b)) {
    return;
  }
  bool dominated =
      def.block == b ? def.index < index : cfg_.dominates(def.block, b);
  if (!dominated) {
    fail(b, id, fmt::format("operand %{} does not dominate its use", v));
  }
}

// One input per predecessor: as many inputs as predecessors, each from a
// distinct predecessor.
void FunctionVerifier::checkPhiInputs(BlockId b, ValueId id, const Inst& inst) {
  const std::vector<BlockId>& preds = cfg_.preds[b];
  if (inst.targets.size() != preds.size()) {
    fail(b, id,
         fmt::format("phi has {} input(s) for {} predecessor(s)",
                     inst.targets.size(), preds.size()));
  }
  std::set<BlockId> seen;
  for (BlockId t : inst.targets) {
    if (t >= f_.blocks.size()) {
      continue; // reported by checkTargets
    }
    if (!std::binary_search(preds.begin(), preds.end(), t)) {
      fail(b, id, fmt::format("b{} is not a predecessor", t));
    } else if (!seen.insert(t).second) {
      fail(b, id, fmt::format("two inputs for predecessor b{}", t));
    }
  }
}

} // namespace

std::vector<std::string> verify(const Module& m) {
  std::vector<std::string> errors;
  for (const Function& f : m.functions) {
    FunctionVerifier(m, f, errors).run();
  }
  return errors;
}

} // namespace mbc::ir
