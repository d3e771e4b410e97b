// The SSA IR of mbc ("mbir"): a module of functions (one per O program and
// the anonymous main), each a list of basic blocks of instructions. An
// instruction defines at most one value; values are named by the id of the
// instruction that defines them. Operations come from opcodes.def.
// docs/ir.md describes every operation and the text form.
#pragma once

#include <mbc/arith.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mbc::ir {

enum class Op : std::uint8_t {
#define OP(Name, Mnemonic, Result, Operands, Flags, Class, Math) Name,
#include "ir/opcodes.def"
};

/// The type of a value. Num is a double that is never vacant; VNum is a
/// double that may be vacant (a variable's value, a phi over such values).
/// Arithmetic takes Num: where a VNum is read as a number, `tonum` makes
/// "vacant reads as 0" explicit, and the vacancy pass removes the `tonum`s
/// it proves needless. Flow is what an NC block or a call asks the control
/// to do next (resume interprets it).
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

/// The evaluator's dispatch (opcodes.def, Class).
enum class OpClass : std::uint8_t { Value, Variable, Effect, Control };

/// The runtime arithmetic an op computes (opcodes.def, Math).
struct OpMath {
  enum Kind : std::uint8_t { None, Binary, Relation } kind = None;

  std::uint8_t op = 0; // a BinOp or a RelOp of <mbc/arith.h>
};

struct OpInfo {
  const char* mnemonic;
  Type result;
  int operands; // -1: variadic
  unsigned flags;
  OpClass cls;
  OpMath math;
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

/// cases[i] of nc/call.macro describes operand i: letter | kind << 8.
inline std::int64_t packWord(char letter, WordKind kind) {
  return static_cast<unsigned char>(letter) |
         (static_cast<std::int64_t>(kind) << 8);
}

inline char wordLetter(std::int64_t w) {
  return static_cast<char>(w & 0xff);
}

inline WordKind wordKind(std::int64_t w) {
  return static_cast<WordKind>((w >> 8) & 0xff);
}

/// cases[i] of dprnt/bprnt describes item i: a text item is str << 1 (str
/// indexes Module::strings), a value item is (c * 10 + d) << 1 | 1 and takes
/// the next operand.
inline std::int64_t packText(std::uint32_t str) {
  return static_cast<std::int64_t>(str) << 1;
}

inline std::int64_t packFormat(int intDigits, int fracDigits) {
  return (static_cast<std::int64_t>(intDigits * 10 + fracDigits) << 1) | 1;
}

struct Inst {
  Op op = Op::Unreachable;
  Type type = Type::None;
  BlockId block = 0;
  std::uint32_t line = 0;
  std::vector<ValueId> ops;
  double imm = 0;                  // const
  std::int64_t attr = 0;           // #n, builtin, letter, skip switch, line
  std::uint32_t str = 0;           // Module::strings index + 1 (0: none)
  std::vector<BlockId> targets;    // br, condbr, switch, resume; phi inputs
  std::vector<std::int64_t> cases; // switch/resume N numbers; word/item info
};

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
};

} // namespace mbc::ir
