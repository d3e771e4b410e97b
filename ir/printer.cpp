// The IR text printer (see printer.h and docs/ir.md). It must also print
// malformed IR, since the verifier quotes the instructions it rejects: a
// missing operand, target or string prints as `?` instead of crashing.
#include "ir/printer.h"

#include <fmt/format.h>

#include <array>
#include <iterator>

namespace mbc::ir {

namespace {

constexpr int kBuiltins = 0
#define BUILTIN(Id, Name, Arity) +1
#include <mbc/builtins.def>
    ;

constexpr std::array<std::string_view, 5> kWordKinds = {"int", "dec", "val",
                                                        "var", "nvar"};

/// Prints what follows the mnemonic of one instruction.
class OperandPrinter {
public:
  OperandPrinter(const Module& m, const Inst& inst, std::string& out)
      : module_(m), inst_(inst), out_(out) {}

  void print();

private:
  template <typename... Args>
  void put(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(out_), format,
                   std::forward<Args>(args)...);
  }

  void operand(std::size_t i);
  void target(std::size_t i);
  void string(std::size_t index);
  void valueList(std::size_t from);
  void words(std::size_t from);
  void items();
  void phi();
  void caseTable(std::size_t firstTarget);
  void message();

  const Module& module_;
  const Inst& inst_;
  std::string& out_;
};

void OperandPrinter::operand(std::size_t i) {
  if (i < inst_.ops.size()) {
    put("%{}", inst_.ops[i]);
  } else {
    out_ += "%?";
  }
}

void OperandPrinter::target(std::size_t i) {
  if (i < inst_.targets.size()) {
    put("b{}", inst_.targets[i]);
  } else {
    out_ += "b?";
  }
}

void OperandPrinter::string(std::size_t index) {
  if (index < module_.strings.size()) {
    out_ += quoteString(module_.strings[index]);
  } else {
    out_ += "?";
  }
}

// ` %a, %b` for operands from..end.
void OperandPrinter::valueList(std::size_t from) {
  for (std::size_t i = from; i < inst_.ops.size(); ++i) {
    out_ += i == from ? " " : ", ";
    operand(i);
  }
}

// `X:int %3` per operand from..end; cases[i] describes operand i.
void OperandPrinter::words(std::size_t from) {
  std::size_t n = std::max(inst_.ops.size(), inst_.cases.size());
  for (std::size_t i = from; i < n; ++i) {
    out_ += i == 0 ? " " : ", ";
    std::int64_t w = i < inst_.cases.size() ? inst_.cases[i] : 0;
    char letter = wordLetter(w);
    out_ += letter >= 'A' && letter <= 'Z' ? letter : '?';
    put(":{} ", wordKindName(wordKind(w)));
    operand(i);
  }
}

// `"TEXT", %3[53]`: a value item takes the next operand.
void OperandPrinter::items() {
  std::size_t next = 0;
  for (std::size_t i = 0; i < inst_.cases.size(); ++i) {
    out_ += i == 0 ? " " : ", ";
    std::int64_t item = inst_.cases[i];
    if (item & 1) {
      operand(next++);
      put("[{}]", item >> 1);
    } else {
      string(static_cast<std::size_t>(item >> 1));
    }
  }
}

void OperandPrinter::phi() {
  out_ += inst_.type == Type::Num ? " num" : " vnum";
  std::size_t n = std::max(inst_.ops.size(), inst_.targets.size());
  for (std::size_t i = 0; i < n; ++i) {
    out_ += i == 0 ? " [" : ", [";
    operand(i);
    out_ += ", ";
    target(i);
    out_ += "]";
  }
}

// ` [10: b3, 20: b7]`: cases[i] goes to targets[firstTarget + i].
void OperandPrinter::caseTable(std::size_t firstTarget) {
  out_ += " [";
  for (std::size_t i = 0; i < inst_.cases.size(); ++i) {
    put("{}{}: ", i == 0 ? "" : ", ", inst_.cases[i]);
    target(firstTarget + i);
  }
  out_ += "]";
}

void OperandPrinter::message() {
  if (inst_.str != 0) {
    out_ += ", ";
    string(inst_.str - 1);
  }
}

void OperandPrinter::print() {
  switch (inst_.op) {
    case Op::Const:
      put(" {}", formatNumber(inst_.imm));
      return;
    case Op::Fn: {
      bool known = inst_.attr >= 0 && inst_.attr < kBuiltins;
      auto b = static_cast<Builtin>(inst_.attr);
      out_ += " ";
      out_ += known ? builtinMnemonic(b) : "?";
      for (std::size_t i = 0; i < inst_.ops.size(); ++i) {
        out_ += ", ";
        operand(i);
      }
      return;
    }
    case Op::RoundAddr: {
      char letter = static_cast<char>(inst_.attr);
      put(" {}, ", letter >= 'A' && letter <= 'Z' ? letter : '?');
      operand(0);
      return;
    }
    case Op::BlockSkip:
    case Op::Begin:
      put(" {}", inst_.attr);
      return;
    case Op::LdVar:
      put(" #{}", inst_.attr);
      return;
    case Op::StVar:
      put(" #{}, ", inst_.attr);
      operand(0);
      message();
      return;
    case Op::StInd:
      valueList(0);
      message();
      return;
    case Op::Nc:
      words(0);
      return;
    case Op::CallMacro:
      out_ += " ";
      operand(0);
      out_ += ", ";
      operand(1);
      words(2);
      return;
    case Op::Dprnt:
    case Op::Bprnt:
      items();
      return;
    case Op::Phi:
      phi();
      return;
    case Op::Trace:
      out_ += " ";
      string(inst_.str - 1);
      for (std::size_t i = 0; i < inst_.ops.size(); ++i) {
        out_ += ", ";
        operand(i);
      }
      return;
    case Op::Raise:
      put(" {}", alarmCode(static_cast<AlarmId>(inst_.attr), 0));
      message();
      return;
    case Op::Br:
      out_ += " ";
      target(0);
      return;
    case Op::CondBr:
      out_ += " ";
      operand(0);
      out_ += ", ";
      target(0);
      out_ += ", ";
      target(1);
      return;
    case Op::Switch:
      out_ += " ";
      operand(0);
      caseTable(0);
      return;
    case Op::Resume:
      out_ += " ";
      operand(0);
      out_ += ", ";
      target(0);
      if (inst_.cases.empty() && inst_.targets.size() == 2) {
        out_ += ", ";
        target(1); // the M99 P landing
      } else {
        caseTable(1);
      }
      return;
    default:
      valueList(0);
      return;
  }
}

// The line an instruction without `!LINE` gets: a begin's own line, else
// the line of the last begin before it in the block.
std::int64_t impliedLine(const Inst& inst, std::int64_t current) {
  return inst.op == Op::Begin ? inst.attr : current;
}

void printBlock(const Module& m, const Function& f, BlockId b,
                std::string& out) {
  fmt::format_to(std::back_inserter(out), "b{}:\n", b);
  std::int64_t current = 0;
  for (ValueId id : f.blocks[b].insts) {
    out += "  ";
    out += printInst(m, f, id);
    if (id < f.insts.size()) {
      const Inst& inst = f.insts[id];
      std::int64_t implied = impliedLine(inst, current);
      if (static_cast<std::int64_t>(inst.line) != implied) {
        fmt::format_to(std::back_inserter(out), " !{}", inst.line);
      }
      if (inst.op == Op::Begin) {
        current = inst.attr;
      }
    }
    out += "\n";
  }
}

} // namespace

int builtinCount() {
  return kBuiltins;
}

std::string_view builtinMnemonic(Builtin b) {
  return b == Builtin::Atan2 ? "ATAN2" : builtinName(b);
}

bool builtinFromMnemonic(std::string_view name, Builtin& out) {
  for (int i = 0; i < kBuiltins; ++i) {
    if (builtinMnemonic(static_cast<Builtin>(i)) == name) {
      out = static_cast<Builtin>(i);
      return true;
    }
  }
  return false;
}

std::string_view wordKindName(WordKind k) {
  auto i = static_cast<std::size_t>(k);
  return i < kWordKinds.size() ? kWordKinds[i] : "?";
}

bool wordKindFromName(std::string_view name, WordKind& out) {
  for (std::size_t i = 0; i < kWordKinds.size(); ++i) {
    if (kWordKinds[i] == name) {
      out = static_cast<WordKind>(i);
      return true;
    }
  }
  return false;
}

std::string formatNumber(double v) {
  return fmt::format("{}", v);
}

std::string quoteString(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
    }
    out += c;
  }
  out += '"';
  return out;
}

std::string printInst(const Module& m, const Function& f, ValueId id) {
  if (id >= f.insts.size()) {
    return fmt::format("%{} (no such instruction)", id);
  }
  const Inst& inst = f.insts[id];
  const OpInfo& info = opInfo(inst.op);
  std::string out;
  if (info.result != Type::None) {
    out = fmt::format("%{} = ", id);
  }
  out += info.mnemonic;
  OperandPrinter(m, inst, out).print();
  return out;
}

std::string print(const Module& m, const Function& f) {
  std::string out = "func @" + f.name;
  if (f.number >= 0) {
    out += fmt::format(" #{}", f.number);
  }
  out += " " + quoteString(f.file) + " {\n";
  for (BlockId b = 0; b < f.blocks.size(); ++b) {
    printBlock(m, f, b, out);
  }
  out += "}\n";
  return out;
}

std::string print(const Module& m) {
  std::string out;
  for (std::size_t i = 0; i < m.functions.size(); ++i) {
    out += i == 0 ? "" : "\n";
    out += print(m, m.functions[i]);
  }
  return out;
}

} // namespace mbc::ir
