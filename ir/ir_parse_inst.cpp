// The IR text parser, one instruction: `[%N =] mnemonic operands [!LINE]`.
// The operand syntax of each operation mirrors OperandPrinter in
// printer.cpp; counts are not checked here (the verifier does that).
#include "ir/ir_parse_internal.h"
#include "ir/printer.h"
#include <mbc/addresses.h>

#include <fmt/format.h>

namespace mbc::ir::parse {

namespace {

/// Fills the operands, targets and payload of one instruction whose
/// mnemonic is read.
class OperandParser {
public:
  OperandParser(Cursor& c, Module& m, Inst& inst)
      : c_(c), module_(m), inst_(inst) {}

  void parse();

private:
  bool atOperandEnd() { return c_.atEol() || c_.peek() == '!'; }

  char letter();
  AlarmId alarm();
  void valueList();
  Builtin fn();
  void words(Words& into);
  AddressWord word();
  PrintItems items();
  void phi();
  void caseTable(SequenceCases& into);
  StringRef message();

  template <class T> T& data() { return inst_.get<T>(); }

  Cursor& c_;
  Module& module_;
  Inst& inst_;
};

// An address letter: one of A..Z.
char OperandParser::letter() {
  TextPos at = c_.pos();
  std::string_view w = c_.word("an address letter");
  if (w.size() != 1 || ((w[0] < 'A' || w[0] > 'Z') && !isCommaWord(w[0]))) {
    Cursor::failAt(at, fmt::format("'{}' is not an address letter", w));
  }
  return w[0];
}

// alarm = CODE ;  "PS0114", "MBC0001"
AlarmId OperandParser::alarm() {
  TextPos at = c_.pos();
  std::string_view w = c_.word("an alarm code");
  const AlarmId id = alarmFromCode(w);
  if (id == AlarmId::None) {
    Cursor::failAt(at, fmt::format("'{}' is not an alarm code", w));
  }
  return id;
}

// values = [value {"," value}] ;
void OperandParser::valueList() {
  if (atOperandEnd()) {
    return;
  }
  do {
    inst_.ops.push_back(c_.value());
  } while (c_.accept(','));
}

// fn = NAME {"," value} ;
Builtin OperandParser::fn() {
  c_.skipBlanks();
  TextPos at = c_.pos();
  std::string_view name = c_.word("a builtin name");
  Builtin b{};
  if (!builtinFromMnemonic(name, b)) {
    Cursor::failAt(at, fmt::format("unknown builtin '{}'", name));
  }
  while (c_.accept(',')) {
    inst_.ops.push_back(c_.value());
  }
  return b;
}

// word = LETTER ":" kind value (a, c, r: ,A ,C ,R) ; kind = "int" | "dec" |
// "val" | "var" | "nvar"
AddressWord OperandParser::word() {
  char l = letter();
  c_.expect(':');
  c_.skipBlanks();
  TextPos at = c_.pos();
  std::string_view name = c_.word("a word kind");
  WordKind kind{};
  if (!wordKindFromName(name, kind)) {
    Cursor::failAt(at, fmt::format("unknown word kind '{}'", name));
  }
  inst_.ops.push_back(c_.value());
  return {l, kind};
}

// words = [word {"," word}] ;
void OperandParser::words(Words& into) {
  if (atOperandEnd()) {
    return;
  }
  do {
    into.words.push_back(word());
  } while (c_.accept(','));
}

// items = [item {"," item}] ; item = string | value "[" integer "]" ;
PrintItems OperandParser::items() {
  PrintItems p;
  if (atOperandEnd()) {
    return p;
  }
  do {
    if (c_.peek() == '"') {
      p.items.push_back({module_.intern(c_.string())});
      continue;
    }
    inst_.ops.push_back(c_.value());
    c_.expect('[');
    std::int64_t format = c_.integer("a print format");
    if (format < 0 || format > 99) {
      c_.fail("print format out of range");
    }
    c_.expect(']');
    p.items.push_back({0, static_cast<std::uint8_t>(format / 10),
                       static_cast<std::uint8_t>(format % 10)});
  } while (c_.accept(','));
  return p;
}

// phi = ("num" | "vnum") [input {"," input}] ; input = "[" value "," block "]"
// ;
void OperandParser::phi() {
  c_.skipBlanks();
  TextPos at = c_.pos();
  std::string_view type = c_.word("the phi's type, num or vnum");
  if (type != "num" && type != "vnum") {
    Cursor::failAt(at,
                   fmt::format("phi type '{}' is neither num nor vnum", type));
  }
  inst_.type = type == "num" ? Type::Num : Type::VNum;
  if (atOperandEnd()) {
    return;
  }
  do {
    c_.expect('[');
    inst_.ops.push_back(c_.value());
    c_.expect(',');
    inst_.targets.push_back(c_.block());
    c_.expect(']');
  } while (c_.accept(','));
}

// table = "[" [integer ":" block {"," integer ":" block}] "]" ;
void OperandParser::caseTable(SequenceCases& into) {
  c_.expect('[');
  if (c_.accept(']')) {
    return;
  }
  do {
    into.numbers.push_back(c_.integer("a sequence number"));
    c_.expect(':');
    inst_.targets.push_back(c_.block());
  } while (c_.accept(','));
  c_.expect(']');
}

// message = ["," string] ;
StringRef OperandParser::message() {
  return c_.accept(',') ? module_.intern(c_.string()) : 0;
}

void OperandParser::parse() {
  inst_.data = payloadOf(inst_.op);
  switch (opInfo(inst_.op).format) {
    case Format::Plain:
      valueList();
      return;
    case Format::Constant:
      data<Number>().value = c_.number();
      return;
    case Format::Function:
      data<BuiltinFn>().fn = fn();
      return;
    case Format::RoundAddress:
      data<AddressLetter>().letter = letter();
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      return;
    case Format::Parameter:
      data<Number>().value = c_.number();
      for (int i = 0; i < 3; ++i) {
        c_.expect(',');
        inst_.ops.push_back(c_.value());
      }
      return;
    case Format::Skip:
      data<SkipSwitch>().number =
          static_cast<int>(c_.integer("a skip switch", INT32_MIN, INT32_MAX));
      return;
    case Format::Line:
      data<SourceLine>().line = static_cast<std::uint32_t>(
          c_.integer("a line number", 0, UINT32_MAX));
      return;
    case Format::Load:
      c_.expect('#');
      data<VarNumber>().number = c_.integer("a variable number");
      return;
    case Format::Store:
      c_.expect('#');
      data<VarNumber>().number = c_.integer("a variable number");
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      data<VarNumber>().message = message();
      return;
    case Format::IndirectStore:
      inst_.ops.push_back(c_.value());
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      data<Message>().text = message();
      return;
    case Format::Block:
      words(data<Words>());
      return;
    case Format::MacroCall:
      inst_.ops.push_back(c_.value());
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      if (c_.accept(',')) {
        words(data<Words>());
      }
      return;
    case Format::Print:
      data<PrintItems>() = items();
      return;
    case Format::PhiInputs:
      phi();
      return;
    case Format::Template:
      data<Message>().text = module_.intern(c_.string());
      while (c_.accept(',')) {
        inst_.ops.push_back(c_.value());
      }
      return;
    case Format::Alarm:
      data<AlarmRaise>().alarm = alarm();
      data<AlarmRaise>().detail = message();
      return;
    case Format::Jump:
      inst_.targets.push_back(c_.block());
      return;
    case Format::Branch:
      inst_.ops.push_back(c_.value());
      for (int i = 0; i < 2; ++i) {
        c_.expect(',');
        inst_.targets.push_back(c_.block());
      }
      return;
    case Format::Table:
      inst_.ops.push_back(c_.value());
      caseTable(data<SequenceCases>());
      return;
    case Format::Resumption:
      inst_.ops.push_back(c_.value());
      c_.expect(',');
      inst_.targets.push_back(c_.block());
      if (c_.accept(',')) {
        inst_.targets.push_back(c_.block()); // the M99 P landing
        data<SequenceCases>().landing = true;
      } else {
        caseTable(data<SequenceCases>());
      }
      return;
  }
}

} // namespace

ParsedInst parseInst(Cursor& c, Module& m) {
  ParsedInst p;
  c.skipBlanks();
  p.pos = c.pos();
  if (c.peek() == '%') {
    p.id = c.value();
    p.hasId = true;
    c.expect('=');
  }
  c.skipBlanks();
  TextPos at = c.pos();
  std::string mnemonic(c.word("an operation"));
  Op op{};
  if (!opFromMnemonic(mnemonic, op)) {
    Cursor::failAt(at, fmt::format("unknown operation '{}'", mnemonic));
  }
  const OpInfo& info = opInfo(op);
  if (p.hasId && info.result == Type::None) {
    Cursor::failAt(p.pos, fmt::format("'{}' defines no value", mnemonic));
  }
  if (!p.hasId && info.result != Type::None) {
    Cursor::failAt(at, fmt::format("'{}' defines a value: write '%N = {}'",
                                   mnemonic, mnemonic));
  }
  p.inst.op = op;
  p.inst.type = info.result;
  OperandParser(c, m, p.inst).parse();
  if (c.accept('!')) {
    std::int64_t line = c.integer("a line number");
    if (line < 0 || line > UINT32_MAX) {
      c.fail("line number out of range");
    }
    p.inst.line = static_cast<std::uint32_t>(line);
    p.hasLine = true;
  }
  c.endLine();
  return p;
}

} // namespace mbc::ir::parse
