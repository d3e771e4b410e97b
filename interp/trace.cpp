// --trace: one line per executed block with its values substituted.
#include "frontend/lexer.h"
#include "interp/interpreter.h"

namespace mbc {

namespace {

std::string wordsText(const std::vector<mbrt_word>& words) {
  std::string out;
  for (const mbrt_word& w : words) {
    if (!out.empty()) {
      out += ' ';
    }
    out += fmt::format("{}{}", w.letter, w.value);
  }
  return out;
}

const char* stmtName(StmtKind k) {
  switch (k) {
    case StmtKind::Dprnt:
      return "DPRNT";
    case StmtKind::Bprnt:
      return "BPRNT";
    case StmtKind::Popen:
      return "POPEN";
    case StmtKind::Pclos:
      return "PCLOS";
    default:
      return "";
  }
}

} // namespace

void Interpreter::trace(const Stmt& s, const std::vector<mbrt_word>* words,
                        const char* outcome) {
  std::string text;
  switch (s.kind) {
    case StmtKind::Nc:
      text = wordsText(*words);
      break;
    case StmtKind::MacroCall:
      text = fmt::format("G65 {} {}", outcome, wordsText(*words));
      break;
    case StmtKind::Assign:
      text = outcome;
      break;
    case StmtKind::IfGoto:
      text = fmt::format("IF [{}] GOTO", outcome);
      break;
    case StmtKind::IfThen:
      text =
          fmt::format("IF [{}] THEN {}",
                      std::string_view(outcome) == "false" ? "false" : "true",
                      std::string_view(outcome) == "false" ? "" : outcome);
      break;
    case StmtKind::Goto:
      text = fmt::format("GOTO {}", outcome);
      break;
    case StmtKind::While:
      text = s.cond ? fmt::format("WHILE [{}] DO{}", outcome, s.loopId)
                    : fmt::format("DO{}", s.loopId);
      break;
    case StmtKind::End:
      text = fmt::format("END{}", s.loopId);
      break;
    default:
      text = outcome ? fmt::format("{} [{}]", stmtName(s.kind), outcome)
                     : stmtName(s.kind);
      break;
  }
  mbrt_trace(ctx_, text.c_str());
}

} // namespace mbc
