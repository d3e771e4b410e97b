// The AST of a Macro B source: files hold programs, programs hold blocks, a
// block holds one statement. Every node keeps its source range.
#pragma once

#include "frontend/source.h"
#include <mbc/alarm.h>
#include <mbc/arith.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mbc {

enum class ExprKind {
  Number,    // literal
  Var,       // #n
  Indirect,  // #[e]
  Neg,       // -e
  Binary,    // arithmetic or bitwise AND/OR/XOR on numbers
  Compare,   // EQ NE GT GE LT LE: a condition
  Logical,   // AND/OR/XOR of two conditions
  Call,      // function
  Parameter, // PRM[n], PRM[n, bit], with /[axis]: args n, then bit, axis
};

struct Expr {
  ExprKind kind = ExprKind::Number;
  SourceRange range;
  bool bracketed = false; // written inside its own [ ] or after a unary +
  double number = 0;      // Number value
  bool hasDecimal = false;
  int var = 0; // Var number
  BinOp binOp = BinOp::Add;
  RelOp relOp = RelOp::Eq;
  Builtin builtin = Builtin::Sin;
  int parameterForm = 0; // Parameter: mbrt_parameter_form bits
  std::vector<std::unique_ptr<Expr>> args;

  bool isCondition() const {
    return kind == ExprKind::Compare || kind == ExprKind::Logical;
  }

  /// A bare variable reference (#n or #[e], not in brackets): the only
  /// expression whose value can be vacant (spec §2.3).
  bool isBareVariable() const {
    return !bracketed && (kind == ExprKind::Var || kind == ExprKind::Indirect);
  }
};

using ExprPtr = std::unique_ptr<Expr>;

enum class WordKind { IntLiteral, DecLiteral, Value };

/// An address word: letter and value. A negated bare variable (X-#1) is
/// still a bare variable: it drops the word when vacant.
struct Word {
  char letter = 0;
  WordKind kind = WordKind::Value;
  bool bareVariable = false;
  ExprPtr value;
  SourceRange range;
  // M98 <DRILL>: the P of a call by name; the semantic checks write the
  // program's number (kFirstNamedProgram...) into `value`.
  std::string calledName;
};

struct VarTarget {
  int number = 0; // when index is null
  ExprPtr index;  // #[e]
  SourceRange range;
};

struct PrintItem {
  std::string text; // literal text when value is null
  ExprPtr value;    // #n / #[e]
  int intDigits = 0;
  int fracDigits = 0;
  SourceRange range;
};

enum class StmtKind {
  Empty,     // only N, comments, or nothing
  Assign,    // #n = e
  IfGoto,    // IF [c] GOTO e
  IfThen,    // IF [c] THEN #n = e
  Goto,      // GOTO e
  While,     // WHILE [c] DOm, or DOm alone (cond null)
  End,       // ENDm
  Nc,        // NC words (incl. M98/M99/M30)
  MacroCall, // G65 P L args
  Dprnt,
  Bprnt,
  Popen,
  Pclos,
};

struct Stmt {
  StmtKind kind = StmtKind::Empty;
  SourceRange range;
  VarTarget target;             // Assign, IfThen
  ExprPtr value;                // Assign/IfThen value, Goto target
  ExprPtr cond;                 // IfGoto, IfThen, While
  std::string message;          // comment after an assignment (#3000/#3006)
  int loopId = 0;               // While, End
  int match = -1;               // While: index of its END; End: of its DO
  std::optional<int> gotoBlock; // IfGoto/Goto with a constant target
  std::vector<Word> words;      // Nc; MacroCall arguments
  // MacroCall: the G codes written before G65 (G57 G65 P...), which the
  // parser turns into an NC block of their own ahead of the call.
  std::vector<Word> leadCodes;
  ExprPtr program;              // MacroCall P
  std::string calledName;       // MacroCall by name: G65 <BOLT>
  ExprPtr repeat;               // MacroCall L (may be null)
  std::vector<PrintItem> items; // Dprnt/Bprnt
  // Nc between G10 L52 and G11: N is a parameter number, not a label.
  bool parameterData = false;
};

struct Block {
  SourceRange range;
  int line = 0;
  int seq = -1;      // N number, -1 when absent
  int skipLevel = 0; // 0: no '/', 1..9: '/n'
  Stmt stmt;
  // A block mbc cannot read raises this alarm when it executes, as the
  // control does; `stmt` then only keeps what the loop structure needs
  // (a WHILE or END). AlarmId::None: an ordinary block.
  AlarmId alarm = AlarmId::None;
  std::string alarmDetail; // the diagnostic's message
};

struct Program {
  std::string name; // "O1000", "<NAME>" or "MAIN" for an anonymous main
  // O number; a named program's number for calls (kFirstNamedProgram...,
  // given by the semantic checks); -1 for an anonymous main.
  int number = -1;
  // A second program of the same name: the control keeps the first (the
  // semantic checks drop this one after reporting it).
  bool duplicate = false;
  SourceRange range;
  std::uint32_t file = 0;
  std::vector<Block> blocks;
};

struct Unit {
  std::vector<Program> programs; // every program of every file, in order
};

} // namespace mbc
