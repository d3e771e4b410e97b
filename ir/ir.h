// The SSA IR of mbc ("mbir"): a module of functions (one per O program and
// the anonymous main), each a list of basic blocks of instructions. An
// instruction defines at most one value; values are named by the id of the
// instruction that defines them. Operations come from opcodes.def.
// docs/ir.md describes every operation and the text form.
#pragma once

#include <mbc/alarm.h>
#include <mbc/arith.h>

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace mbc::ir {

enum class Op : std::uint8_t {
#define OP(Name, Mnemonic, Result, Operands, Takes, Flags, Math, Format) Name,
#include "ir/opcodes.def"
};

enum class Type : std::uint8_t { None, Num, VNum, Bool, Flow };

enum OpFlag : unsigned {
  Pure = 0,
  Terminator = 1U << 0,
  ReadsVars = 1U << 1,
  WritesVars = 1U << 2,
  SideEffect = 1U << 3,
  MayAlarm = 1U << 4,
  ReadsState = 1U << 5,  // machine state that NC blocks change
  Cseable = 1U << 6,     // equal operands give equal results
  Commutative = 1U << 7, // the two operands may swap
};

/// What the value operands of an op are read as (opcodes.def, Takes).
enum class OperandRule : std::uint8_t {
  Num,
  VNum,
  Bool,
  Flow,
  AnyValue,   // any value but a flow
  OwnType,    // the instruction's own type (phi)
  IndexValue, // a number, then a value that may be vacant (stind)
};

/// The operand syntax, payload and targets of an op (formats.def).
enum class Format : std::uint8_t {
#define FORMAT(Name, Payload) Name,
#include "ir/formats.def"
};

/// The runtime arithmetic an op computes (opcodes.def, Math).
struct OpMath {
  enum Kind : std::uint8_t { None, Binary, Relation } kind = None;

  std::uint8_t op = 0; // a BinOp or a RelOp of <mbc/arith.h>
};

struct OpInfo {
  const char* mnemonic;
  Type result;
  int operands; // -1: variadic
  OperandRule takes;
  unsigned flags;
  OpMath math;
  Format format;
};

const OpInfo& opInfo(Op op);

/// add ... xor: the BinOp they compute; eq ... le: the RelOp.
std::optional<BinOp> binaryOf(Op op);
std::optional<RelOp> relationOf(Op op);
/// The op with this mnemonic; false when there is none.
bool opFromMnemonic(const std::string& mnemonic, Op& out);

using ValueId = std::uint32_t; // index into Function::insts
using BlockId = std::uint32_t; // index into Function::blocks
inline constexpr ValueId kNoValue = 0xffffffffU;

/// How an address word's value is handed to the runtime (nc, call.macro).
enum class WordKind : std::uint8_t {
  Int,    // literal without decimal point ("X10")
  Dec,    // literal with decimal point ("X10.")
  Val,    // [expression]: a real value, vacant reads as 0
  Var,    // bare variable "X#1": the word is dropped when it is vacant
  NegVar, // "X-#1": dropped when vacant, else negated
};

/// A string of Module::strings: its index + 1, 0 for none.
using StringRef = std::uint32_t;

// The payloads: what an instruction holds besides its operands and
// targets. The op's format (formats.def) names the one it has; the verifier
// checks it.

struct NoData {};

/// const: the value.
struct Number {
  double value = 0;
};

/// ldvar, stvar: the variable; stvar's optional message (an assignment
/// whose text the trace quotes).
struct VarNumber {
  std::int64_t number = 0;
  StringRef message = 0;
};

/// stind: the optional message, as stvar's; trace: the template.
struct Message {
  StringRef text = 0;
};

/// fn: the builtin it calls.
struct BuiltinFn {
  Builtin fn{};
};

/// round.addr: the address whose least increment ROUND rounds to.
struct AddressLetter {
  char letter = 'A';
};

/// blockskip: the switch /1../9.
struct SkipSwitch {
  int number = 1;
};

/// begin: the source line of the block.
struct SourceLine {
  std::uint32_t line = 0;
};

/// One address word of an NC block or a G65 call.
struct AddressWord {
  char letter = 'A';
  WordKind kind = WordKind::Val;

  bool operator==(const AddressWord&) const = default;
};

/// nc, call.macro: one word per word operand. nc's words are its
/// operands; call.macro's start after P and L (firstWordOperand).
struct Words {
  std::vector<AddressWord> words;
};

/// One item of a print statement: a text, or a value printed with
/// intDigits.fracDigits (bprnt: fracDigits only) that takes the next
/// operand.
struct PrintItem {
  StringRef text = 0; // 0: a value
  std::uint8_t intDigits = 0;
  std::uint8_t fracDigits = 0;

  bool isValue() const { return text == 0; }

  bool operator==(const PrintItem&) const = default;
};

/// dprnt, bprnt: the items in order.
struct PrintItems {
  std::vector<PrintItem> items;
};

/// raise: the alarm and the diagnostic printed after it.
struct AlarmRaise {
  AlarmId alarm = AlarmId::None;
  StringRef detail = 0;
};

/// switch: numbers[i] goes to targets[i]. resume: targets[0] is NEXT; with
/// `landing` an M99 P goes to targets[1] (the landing block reads the N),
/// otherwise numbers[i] goes to targets[i + 1] (firstCaseTarget).
struct SequenceCases {
  std::vector<std::int64_t> numbers;
  bool landing = false;
};

using Payload = std::variant<NoData, Number, VarNumber, Message, BuiltinFn,
                             AddressLetter, SkipSwitch, SourceLine, Words,
                             PrintItems, AlarmRaise, SequenceCases>;

/// A visitor of a Payload from one lambda per alternative.
template <class... Fs> struct Overloaded : Fs... { using Fs::operator()...; };
template <class... Fs> Overloaded(Fs...) -> Overloaded<Fs...>;

/// The payload a new instruction of this op starts with (its format's).
Payload payloadOf(Op op);

/// True when `p` holds the alternative the format of `op` names.
bool payloadFits(Op op, const Payload& p);

struct Inst {
  Op op = Op::Unreachable;
  Type type = Type::None;
  BlockId block = 0;
  std::uint32_t line = 0;
  std::vector<ValueId> ops;
  /// The blocks it names: a terminator's successors (br: one; condbr: true
  /// then false; switch and resume: see SequenceCases), a phi's incoming
  /// blocks (targets[i] gives ops[i]).
  std::vector<BlockId> targets;
  Payload data;

  /// The payload of the op's format; only after the verifier, or where the
  /// op is known, since a mismatch throws.
  template <class T> T& get() { return std::get<T>(data); }

  template <class T> const T& get() const { return std::get<T>(data); }
};

/// call.macro's words follow its P and L operands; nc's start at 0.
inline std::size_t firstWordOperand(Op op) {
  return op == Op::CallMacro ? 2 : 0;
}

/// switch's cases start at targets[0]; resume's after NEXT.
inline std::size_t firstCaseTarget(Op op) {
  return op == Op::Resume ? 1 : 0;
}

struct Block {
  std::vector<ValueId> insts; // in order; the last is the terminator
};

struct Function {
  std::string name; // "O1000", "<NAME>", "MAIN"
  int number = -1;  // O number, -1 for named and anonymous programs
  std::string file; // source file, for alarms
  std::vector<Inst> insts;
  std::vector<Block> blocks; // blocks[0] is the entry
};

struct Module {
  std::vector<Function> functions;
  std::vector<std::string> strings; // messages and print text

  /// The reference of `s`, added once however often it is interned.
  StringRef intern(const std::string& s);

  /// The function of O number `number`; nullptr for none.
  const Function* numbered(int number) const;

  /// The string `ref` names; nullptr for none or one out of range.
  const std::string* text(StringRef ref) const {
    return ref != 0 && ref <= strings.size() ? &strings[ref - 1] : nullptr;
  }
};

} // namespace mbc::ir
