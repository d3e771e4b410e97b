// The IR text printer (see printer.h and docs/ir.md). It must also print
// malformed IR, since the verifier quotes the instructions it rejects: a
// missing operand, target or string prints as `?` instead of crashing.
#include "ir/printer.h"

#include <mbc/addresses.h>

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
  void string(StringRef ref);
  void valueList(std::size_t from);
  void words(const Words& w, std::size_t from);
  void items(const PrintItems& p);
  void phi();
  void caseTable(const SequenceCases& c, std::size_t firstTarget);
  void resume(const SequenceCases& c);
  void message(StringRef ref);
  void payload();

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

void OperandPrinter::string(StringRef ref) {
  if (const std::string* s = module_.text(ref)) {
    out_ += quoteString(*s);
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

// `X:int %3` per word (`c:dec %4` for ,C); word i is operand from + i.
void OperandPrinter::words(const Words& w, std::size_t from) {
  std::size_t n = std::max(inst_.ops.size(), from + w.words.size());
  for (std::size_t i = from; i < n; ++i) {
    out_ += i == 0 ? " " : ", ";
    AddressWord word =
        i - from < w.words.size() ? w.words[i - from] : AddressWord{'?', {}};
    out_ +=
        (word.letter >= 'A' && word.letter <= 'Z') || isCommaWord(word.letter)
            ? word.letter
            : '?';
    put(":{} ", wordKindName(word.kind));
    operand(i);
  }
}

// `"TEXT", %3[53]`: a value item takes the next operand.
void OperandPrinter::items(const PrintItems& p) {
  std::size_t next = 0;
  for (std::size_t i = 0; i < p.items.size(); ++i) {
    out_ += i == 0 ? " " : ", ";
    const PrintItem& item = p.items[i];
    if (item.isValue()) {
      operand(next++);
      put("[{}]", item.intDigits * 10 + item.fracDigits);
    } else {
      string(item.text);
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

// ` [10: b3, 20: b7]`: numbers[i] goes to targets[firstTarget + i].
void OperandPrinter::caseTable(const SequenceCases& c,
                               std::size_t firstTarget) {
  out_ += " [";
  for (std::size_t i = 0; i < c.numbers.size(); ++i) {
    put("{}{}: ", i == 0 ? "" : ", ", c.numbers[i]);
    target(firstTarget + i);
  }
  out_ += "]";
}

void OperandPrinter::resume(const SequenceCases& c) {
  out_ += " ";
  operand(0);
  out_ += ", ";
  target(0);
  if (c.landing) {
    out_ += ", ";
    target(1);
  } else {
    caseTable(c, 1);
  }
}

void OperandPrinter::message(StringRef ref) {
  if (ref != 0) {
    out_ += ", ";
    string(ref);
  }
}

// The operands of an instruction whose payload is not its op's: the
// verifier quotes such IR.
void OperandPrinter::payload() {
  valueList(0);
  out_ += " <payload?>";
}

void OperandPrinter::print() {
  if (!payloadFits(inst_.op, inst_.data)) {
    payload();
    return;
  }
  switch (opInfo(inst_.op).format) {
    case Format::Plain:
      valueList(0);
      return;
    case Format::Constant:
      put(" {}", formatNumber(inst_.get<Number>().value));
      return;
    case Format::Function: {
      auto b = inst_.get<BuiltinFn>().fn;
      bool known = static_cast<int>(b) < kBuiltins;
      out_ += " ";
      out_ += known ? builtinMnemonic(b) : "?";
      for (std::size_t i = 0; i < inst_.ops.size(); ++i) {
        out_ += ", ";
        operand(i);
      }
      return;
    }
    case Format::RoundAddress: {
      char letter = inst_.get<AddressLetter>().letter;
      put(" {}, ", letter >= 'A' && letter <= 'Z' ? letter : '?');
      operand(0);
      return;
    }
    case Format::Parameter:
      put(" {}, ", inst_.get<Number>().value);
      operand(0);
      put(", ");
      operand(1);
      put(", ");
      operand(2);
      return;
    case Format::Skip:
      put(" {}", inst_.get<SkipSwitch>().number);
      return;
    case Format::Line:
      put(" {}", inst_.get<SourceLine>().line);
      return;
    case Format::Load:
      put(" #{}", inst_.get<VarNumber>().number);
      return;
    case Format::Store:
      put(" #{}, ", inst_.get<VarNumber>().number);
      operand(0);
      message(inst_.get<VarNumber>().message);
      return;
    case Format::IndirectStore:
      valueList(0);
      message(inst_.get<Message>().text);
      return;
    case Format::Block:
      words(inst_.get<Words>(), 0);
      return;
    case Format::MacroCall:
      out_ += " ";
      operand(0);
      out_ += ", ";
      operand(1);
      words(inst_.get<Words>(), 2);
      return;
    case Format::Print:
      items(inst_.get<PrintItems>());
      return;
    case Format::PhiInputs:
      phi();
      return;
    case Format::Template:
      out_ += " ";
      string(inst_.get<Message>().text);
      for (std::size_t i = 0; i < inst_.ops.size(); ++i) {
        out_ += ", ";
        operand(i);
      }
      return;
    case Format::Alarm:
      put(" {}", alarmCode(inst_.get<AlarmRaise>().alarm, 0));
      message(inst_.get<AlarmRaise>().detail);
      return;
    case Format::Jump:
      out_ += " ";
      target(0);
      return;
    case Format::Branch:
      out_ += " ";
      operand(0);
      out_ += ", ";
      target(0);
      out_ += ", ";
      target(1);
      return;
    case Format::Table:
      out_ += " ";
      operand(0);
      caseTable(inst_.get<SequenceCases>(), 0);
      return;
    case Format::Resumption:
      resume(inst_.get<SequenceCases>());
      return;
  }
}

// The line an instruction without `!LINE` gets: a begin's own line, else
// the line of the last begin before it in the block.
std::int64_t impliedLine(const Inst& inst, std::int64_t current) {
  const auto* begin = std::get_if<SourceLine>(&inst.data);
  return inst.op == Op::Begin && begin != nullptr ? begin->line : current;
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
      current = implied;
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
