// The IR verifier (see verifier.h). Each check reports and goes on, so one
// run lists every problem; checks that index by an id test its range first,
// because malformed IR is exactly what arrives here.
#include "ir/verifier.h"

#include "ir/cfg.h"
#include "ir/printer.h"
#include <mbc/addresses.h>
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

// The type operand i must have (opcodes.def, Takes); VNum accepts Num too,
// None any value but a flow.
Type operandType(const Inst& inst, std::size_t i) {
  switch (opInfo(inst.op).takes) {
    case OperandRule::Num:
      return Type::Num;
    case OperandRule::VNum:
      return Type::VNum;
    case OperandRule::Bool:
      return Type::Bool;
    case OperandRule::Flow:
      return Type::Flow;
    case OperandRule::AnyValue:
      return Type::None;
    case OperandRule::OwnType:
      return inst.type;
    case OperandRule::IndexValue:
      return i == 0 ? Type::Num : Type::VNum;
  }
  return Type::Num;
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

// What an instruction with a fitting payload must have: its number of block
// targets, and of value operands (-1: the targets decide, for phis).
struct Shape {
  std::size_t targets = 0;
  std::ptrdiff_t operands = 0;
};

Shape expectedShape(const Module& m, const Inst& inst) {
  const OpInfo& info = opInfo(inst.op);
  switch (info.format) {
    case Format::Plain:
    case Format::Constant:
    case Format::RoundAddress:
    case Format::Parameter:
    case Format::Skip:
    case Format::Line:
    case Format::Load:
    case Format::Store:
    case Format::IndirectStore:
    case Format::Alarm:
      break;
    case Format::Function:
      return {0, builtinArity(inst.get<BuiltinFn>().fn)};
    case Format::Block:
    case Format::MacroCall:
      return {0, static_cast<std::ptrdiff_t>(firstWordOperand(inst.op) +
                                             inst.get<Words>().words.size())};
    case Format::Print: {
      const auto& items = inst.get<PrintItems>().items;
      return {0, std::count_if(items.begin(), items.end(),
                               [](const PrintItem& i) { return i.isValue(); })};
    }
    case Format::PhiInputs:
      return {inst.ops.size(), -1};
    case Format::Template: {
      const std::string* t = m.text(inst.get<Message>().text);
      return {0,
              t == nullptr ? -1 : static_cast<std::ptrdiff_t>(traceHoles(*t))};
    }
    case Format::Jump:
      return {1, info.operands};
    case Format::Branch:
      return {2, info.operands};
    case Format::Table:
      return {inst.get<SequenceCases>().numbers.size(), info.operands};
    case Format::Resumption: { // NEXT, then the M99 P landing or the cases
      const SequenceCases& c = inst.get<SequenceCases>();
      return {1 + (c.landing ? 1 : c.numbers.size()), info.operands};
    }
  }
  return {0, info.operands};
}

bool isLetter(std::int64_t c) {
  return (c >= 'A' && c <= 'Z') ||
         (c >= 'a' && c <= 'z' && isCommaWord(static_cast<char>(c)));
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
  void checkShape(BlockId b, ValueId id, const Inst& inst);
  void checkString(BlockId b, ValueId id, StringRef s, std::string_view what);
  void checkPayload(BlockId b, ValueId id, const Inst& inst);
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
  if (payloadFits(inst.op, inst.data)) {
    checkPayload(b, id, inst);
    checkShape(b, id, inst);
  } else {
    fail(b, id,
         fmt::format("the payload is not the one {} has (opcodes.def)",
                     opInfo(inst.op).mnemonic));
  }
  checkOperands(b, index, id, inst);
  if (inst.op == Op::Phi) {
    checkPhiInputs(b, id, inst);
  }
  if (inst.op == Op::RetSeq) {
    checkLanding(b, id);
  }
  // The runtime sets what startseq reads only as the program is entered.
  if (inst.op == Op::StartSeq && b != 0) {
    fail(b, id, "startseq outside the entry block");
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
      if (term != nullptr && term->op == Op::Resume &&
          payloadFits(term->op, term->data) &&
          term->get<SequenceCases>().landing && term->targets.size() == 2 &&
          term->targets[1] == into && term->targets[0] != into) {
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

void FunctionVerifier::checkShape(BlockId b, ValueId id, const Inst& inst) {
  const Shape want = expectedShape(module_, inst);
  auto n = std::ssize(inst.ops);
  if (inst.op == Op::CallMacro && n < 2) {
    fail(b, id, "call.macro needs the operands P and L");
  } else if (want.operands >= 0 && n != want.operands) {
    const Format f = opInfo(inst.op).format;
    std::string why =
        f == Format::Block || f == Format::MacroCall ? " for the words"
        : f == Format::Print                         ? " for the value items"
        : f == Format::Template ? " for the template's holes"
        : f == Format::Function
            ? fmt::format(" for {}", builtinMnemonic(inst.get<BuiltinFn>().fn))
            : "";
    fail(
        b, id,
        fmt::format("expected {} operand(s){}, got {}", want.operands, why, n));
  }
  if (inst.targets.size() != want.targets) {
    fail(b, id,
         fmt::format("expected {} block target(s), got {}", want.targets,
                     inst.targets.size()));
  }
  for (BlockId t : inst.targets) {
    if (t >= f_.blocks.size()) {
      fail(b, id, fmt::format("target b{} does not exist", t));
    }
  }
}

void FunctionVerifier::checkString(BlockId b, ValueId id, StringRef s,
                                   std::string_view what) {
  if (s != 0 && module_.text(s) == nullptr) {
    fail(b, id, fmt::format("{} {} names no string", what, s));
  }
}

// What each payload may hold: one overload per alternative of Payload, so
// that a new payload does not compile until it is checked.
void FunctionVerifier::checkPayload(BlockId b, ValueId id, const Inst& inst) {
  auto bad = [&](const std::string& message) { fail(b, id, message); };
  std::visit(
      Overloaded{
          [](const NoData&) {},
          [](const Number&) {},
          [&](const VarNumber& v) {
            if (v.number < 0) {
              bad("variable number is negative");
            }
            checkString(b, id, v.message, "message");
          },
          [&](const Message& m) {
            if (inst.op == Op::Trace && m.text == 0) {
              bad("trace without a template");
            }
            checkString(b, id, m.text, "message");
          },
          [&](const BuiltinFn& f) {
            if (static_cast<int>(f.fn) >= builtinCount()) {
              bad(fmt::format("unknown builtin {}", static_cast<int>(f.fn)));
            } else if (f.fn == Builtin::Adp) {
              bad("ADP is the adp operation, never fn");
            }
          },
          [&](const AddressLetter& l) {
            if (!isLetter(l.letter)) {
              bad(fmt::format("address {} is not a letter A..Z, a, c or r",
                              static_cast<int>(l.letter)));
            }
          },
          [&](const SkipSwitch& s) {
            if (s.number < 1 || s.number > 9) {
              bad("block skip switch outside 1..9");
            }
          },
          [](const SourceLine&) {},
          [&](const Words& w) {
            for (std::size_t i = 0; i < w.words.size(); ++i) {
              const AddressWord& word = w.words[i];
              if (!isLetter(word.letter) || word.kind > WordKind::NegVar) {
                bad(fmt::format("bad word {} ({}, kind {})", i,
                                static_cast<int>(word.letter),
                                static_cast<int>(word.kind)));
              }
            }
          },
          [&](const PrintItems& p) {
            for (const PrintItem& item : p.items) {
              checkString(b, id, item.text, "text item");
              if (item.intDigits > 9 || item.fracDigits > 9) {
                bad("print format digits outside 0..9");
              }
            }
          },
          [&](const AlarmRaise& r) {
            if (alarmInfo(r.alarm).prefix[0] == '\0') {
              bad(fmt::format("raise of alarm {}, which has no code",
                              static_cast<int>(r.alarm)));
            }
            checkString(b, id, r.detail, "message");
          },
          [&](const SequenceCases& c) {
            if (c.landing && (inst.op != Op::Resume || !c.numbers.empty())) {
              bad("only a resume without cases has a landing");
            }
            std::set<std::int64_t> seen;
            for (std::int64_t n : c.numbers) {
              if (!isSequenceNumber(static_cast<double>(n))) {
                bad(fmt::format("case {} is not a sequence number (1..{})", n,
                                kMaxSequenceNumber));
              } else if (!seen.insert(n).second) {
                bad(fmt::format("case {} appears twice", n));
              }
            }
          },
      },
      inst.data);
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
      continue; // reported by checkShape
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
