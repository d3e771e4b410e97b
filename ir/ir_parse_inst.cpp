// The IR text parser, one instruction: `[%N =] mnemonic operands [!LINE]`.
// The operand syntax of each operation mirrors OperandPrinter in
// printer.cpp; counts are not checked here (the verifier does that).
#include "ir/ir_parse_internal.h"
#include "ir/printer.h"

#include <fmt/format.h>

namespace mbc::ir::parse {

namespace {

/// Fills the operand fields of one instruction whose mnemonic is read.
class OperandParser {
public:
  OperandParser(Cursor& c, Module& m, Inst& inst)
      : c_(c), module_(m), inst_(inst) {}

  void parse();

private:
  bool atOperandEnd() { return c_.atEol() || c_.peek() == '!'; }

  std::uint32_t intern(const std::string& s);
  char letter();
  std::int64_t alarm();
  void valueList();
  void fn();
  void words();
  void word();
  void items();
  void phi();
  void caseTable();
  void message();

  Cursor& c_;
  Module& module_;
  Inst& inst_;
};

std::uint32_t OperandParser::intern(const std::string& s) {
  for (std::size_t i = 0; i < module_.strings.size(); ++i) {
    if (module_.strings[i] == s) {
      return static_cast<std::uint32_t>(i);
    }
  }
  module_.strings.push_back(s);
  return static_cast<std::uint32_t>(module_.strings.size() - 1);
}

// An address letter: one of A..Z.
char OperandParser::letter() {
  TextPos at = c_.pos();
  std::string_view w = c_.word("an address letter");
  if (w.size() != 1 || w[0] < 'A' || w[0] > 'Z') {
    Cursor::failAt(at, fmt::format("'{}' is not an address letter", w));
  }
  return w[0];
}

// alarm = CODE ;  "PS0114", "MBC0001"
std::int64_t OperandParser::alarm() {
  TextPos at = c_.pos();
  std::string_view w = c_.word("an alarm code");
  const AlarmId id = alarmFromCode(w);
  if (id == AlarmId::None) {
    Cursor::failAt(at, fmt::format("'{}' is not an alarm code", w));
  }
  return static_cast<std::int64_t>(id);
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
void OperandParser::fn() {
  c_.skipBlanks();
  TextPos at = c_.pos();
  std::string_view name = c_.word("a builtin name");
  Builtin b{};
  if (!builtinFromMnemonic(name, b)) {
    Cursor::failAt(at, fmt::format("unknown builtin '{}'", name));
  }
  inst_.attr = static_cast<std::int64_t>(b);
  while (c_.accept(',')) {
    inst_.ops.push_back(c_.value());
  }
}

// word = LETTER ":" kind value ; kind = "int" | "dec" | "val" | "var" | "nvar"
void OperandParser::word() {
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
  inst_.cases.push_back(packWord(l, kind));
}

// words = [word {"," word}] ;
void OperandParser::words() {
  if (atOperandEnd()) {
    return;
  }
  do {
    word();
  } while (c_.accept(','));
}

// items = [item {"," item}] ; item = string | value "[" integer "]" ;
void OperandParser::items() {
  if (atOperandEnd()) {
    return;
  }
  do {
    if (c_.peek() == '"') {
      inst_.cases.push_back(packText(intern(c_.string())));
      continue;
    }
    inst_.ops.push_back(c_.value());
    c_.expect('[');
    std::int64_t format = c_.integer("a print format");
    if (format < 0 || format > 99) {
      c_.fail("print format out of range");
    }
    c_.expect(']');
    auto digits = static_cast<int>(format);
    inst_.cases.push_back(packFormat(digits / 10, digits % 10));
  } while (c_.accept(','));
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
void OperandParser::caseTable() {
  c_.expect('[');
  if (c_.accept(']')) {
    return;
  }
  do {
    inst_.cases.push_back(c_.integer("a sequence number"));
    c_.expect(':');
    inst_.targets.push_back(c_.block());
  } while (c_.accept(','));
  c_.expect(']');
}

// message = ["," string] ;  stored as Module::strings index + 1
void OperandParser::message() {
  if (c_.accept(',')) {
    inst_.str = intern(c_.string()) + 1;
  }
}

void OperandParser::parse() {
  switch (inst_.op) {
    case Op::Const:
      inst_.imm = c_.number();
      return;
    case Op::Fn:
      fn();
      return;
    case Op::RoundAddr:
      inst_.attr = letter();
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      return;
    case Op::BlockSkip:
    case Op::Begin:
      inst_.attr = c_.integer("a number");
      return;
    case Op::LdVar:
      c_.expect('#');
      inst_.attr = c_.integer("a variable number");
      return;
    case Op::StVar:
      c_.expect('#');
      inst_.attr = c_.integer("a variable number");
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      message();
      return;
    case Op::StInd:
      inst_.ops.push_back(c_.value());
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      message();
      return;
    case Op::Nc:
      words();
      return;
    case Op::CallMacro:
      // P and L have no word descriptor; cases[0] and [1] are placeholders
      // so that cases[i] still describes operand i.
      inst_.ops.push_back(c_.value());
      c_.expect(',');
      inst_.ops.push_back(c_.value());
      inst_.cases = {0, 0};
      if (c_.accept(',')) {
        words();
      }
      return;
    case Op::Dprnt:
    case Op::Bprnt:
      items();
      return;
    case Op::Phi:
      phi();
      return;
    case Op::Trace:
      inst_.str = intern(c_.string()) + 1;
      while (c_.accept(',')) {
        inst_.ops.push_back(c_.value());
      }
      return;
    case Op::Raise:
      inst_.attr = alarm();
      message();
      return;
    case Op::Br:
      inst_.targets.push_back(c_.block());
      return;
    case Op::CondBr:
      inst_.ops.push_back(c_.value());
      for (int i = 0; i < 2; ++i) {
        c_.expect(',');
        inst_.targets.push_back(c_.block());
      }
      return;
    case Op::Switch:
      inst_.ops.push_back(c_.value());
      caseTable();
      return;
    case Op::Resume:
      inst_.ops.push_back(c_.value());
      c_.expect(',');
      inst_.targets.push_back(c_.block());
      if (c_.accept(',')) {
        inst_.targets.push_back(c_.block()); // the M99 P landing
      } else {
        caseTable();
      }
      return;
    default:
      valueList();
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
