// Trace templates (see trace_text.h).
#include "frontend/trace_text.h"

#include <fmt/format.h>

namespace mbc {

std::string traceTemplate(const Program& p, const Stmt& s, bool taken) {
  switch (s.kind) {
    case StmtKind::Assign:
    case StmtKind::IfThen: {
      if (s.kind == StmtKind::IfThen && !taken) {
        return "IF [false] THEN";
      }
      std::string target = s.target.index ? std::string("#{#}")
                                          : fmt::format("#{}", s.target.number);
      return fmt::format("{}{} = {{}}",
                         s.kind == StmtKind::IfThen ? "IF [true] THEN " : "",
                         target);
    }
    case StmtKind::IfGoto:
      return "IF [{?}] GOTO";
    case StmtKind::Goto:
      return s.gotoBlock ? fmt::format("GOTO N{}", p.blocks[*s.gotoBlock].seq)
                         : std::string("GOTO N{#}");
    case StmtKind::While:
      return s.cond ? fmt::format("WHILE [{{?}}] DO{}", s.loopId)
                    : fmt::format("DO{}", s.loopId);
    case StmtKind::End:
      return fmt::format("END{}", s.loopId);
    default:
      return "";
  }
}

} // namespace mbc
