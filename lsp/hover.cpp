// Hover texts (see hover.h). The facts come from mbc's own tables: the G
// code table the runtime executes by, the system variable map, the
// argument specifications and the calls of the unit.
#include "lsp/hover.h"

#include "frontend/called_programs.h"
#include <mbc/addresses.h>
#include <mbc/alarm.h>
#include <mbc/arith.h>
#include <mbc/calling_codes.h>
#include <mbc/g_codes.h>
#include <mbc/limits.h>
#include <mbc/sysvars.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lsp/m_codes.h"
#include "lsp/navigation.h"

namespace mbc::lsp {

namespace {

/// `code`: the word as the program writes it ("G01").
std::string gCodeHover(std::string_view code, double value, char latheSystem) {
  const int tenths = static_cast<int>(std::lround(value * 10));
  const char column = latheSystem != 0 ? latheSystem : 'M';
  const std::optional<GCodeFacts> facts = gCodeFacts(column, tenths);
  if (!facts) {
    return fmt::format(
        "**{}**: not a G code of the {}. A machine profile can make it a "
        "custom G code that calls O9010-O9019 (parameters 6050-6059); "
        "otherwise a block with it alarms (PS0010).",
        code, latheSystem != 0 ? "0i-TF" : "0i-MF");
  }
  std::string text = fmt::format("**{}**: {}", code, facts->name);
  text += facts->group != 0
              ? fmt::format(" (modal group {:02}, read back in #{})",
                            facts->group, 4000 + facts->group)
              : " (one-shot)";
  text += facts->modelled ? "\n\nmbc executes it."
                          : "\n\nmbc does not execute it yet: a run stops "
                            "at this block with MBC0001.";
  return text;
}

std::string mCodeHover(std::string_view code, double value) {
  if (const std::optional<MCodeText> m = mCodeText(value)) {
    return fmt::format("**{}**: {}: {}", code, m->name, m->effect);
  }
  return fmt::format("**{}**: a machine function: mbc passes it on (the "
                     "toolpath does not change); a profile may make it call "
                     "a subprogram or macro (parameters 6071-6089).",
                     code);
}

/// The argument letters that set local #n: one of specification I, and
/// the I, J, K of specification II.
std::string argumentLetters(int n) {
  const char one = argumentLetter(n);
  std::string letters = one != 0 && (one < 'I' || one > 'K')
                            ? fmt::format("`{}` (specification I)", one)
                            : "";
  if (n >= 4 && n <= 33) {
    const int set = (n - 4) / 3 + 1;
    const char member = static_cast<char>('I' + (n - 4) % 3);
    const std::string two =
        fmt::format("`{}{}` (specification II)", member, set);
    letters = letters.empty()
                  ? two
                  : (set == 1 ? fmt::format("`{}`, or {}", member, two)
                              : fmt::format("{}, or {}", letters, two));
  }
  return letters;
}

std::string variableHover(int n) {
  if (n == 0) {
    return "**#0**: always vacant; it cannot be written.";
  }
  if (isLocal(n)) {
    const std::string letters = argumentLetters(n);
    return fmt::format(
        "**#{}**: local variable of the program or macro that "
        "runs{}",
        n,
        letters.empty()
            ? "."
            : fmt::format("; a G65/G66 argument {} sets it.", letters));
  }
  if (n >= kFirstCommon && n <= kLastCommon) {
    return fmt::format("**#{}**: common variable, shared by every program; "
                       "vacant at power on.",
                       n);
  }
  if (n >= kFirstNonvolatile && n <= kLastNonvolatile) {
    return fmt::format("**#{}**: common variable, kept when the power is off "
                       "(mbc run --state keeps it in a state file).",
                       n);
  }
  if (const std::optional<SystemVariableFacts> facts = systemVariableFacts(n)) {
    std::string text = fmt::format("**#{}**: {}", n, facts->meaning);
    if (!facts->readable) {
      text +=
          fmt::format("\n\nmbc does not model it: a block that reads or "
                      "writes it alarms (PS0115){}",
                      facts->note != nullptr ? fmt::format(": {}", facts->note)
                                             : std::string("."));
      return text;
    }
    text += facts->writable ? "\n\nRead and write." : "\n\nRead only.";
    if (facts->byProfile) {
      text += " It exists on machines whose profile has it.";
    }
    if (facts->note != nullptr) {
      text += fmt::format(" {}", facts->note);
    }
    if (facts->unit != nullptr) {
      text += fmt::format(" Values in {}.", facts->unit);
    }
    return text;
  }
  return fmt::format("**#{}**: no variable of the control: a block that "
                     "reads or writes it alarms (PS0115).",
                     n);
}

/// The calls in `unit` that pass local #n to `program` (G65, G66): "O1000
/// line 16", at most a few.
std::string passedBy(const Unit& unit, const Program& program, int n) {
  constexpr int kMaxSaid = 5;
  std::vector<std::string> calls;
  int more = 0;
  for (const Program& caller : unit.programs) {
    for (const Block& b : caller.blocks) {
      if (calledNumber(b.stmt) != program.number) {
        continue;
      }
      const std::vector<int> locals = argumentLocals(callArguments(b.stmt));
      if (std::find(locals.begin(), locals.end(), n) == locals.end()) {
        continue;
      }
      if (static_cast<int>(calls.size()) < kMaxSaid) {
        calls.push_back(fmt::format("{} line {}", caller.name, b.line));
      } else {
        ++more;
      }
    }
  }
  if (calls.empty()) {
    return "";
  }
  std::string text = "\n\nPassed by ";
  for (std::size_t i = 0; i < calls.size(); ++i) {
    text += (i == 0 ? "" : ", ") + calls[i];
  }
  return text + (more > 0 ? fmt::format(" and {} more.", more) : ".");
}

/// The blocks that jump to N`seq` of `program`.
int jumpsTo(const Program& program, const Block& target) {
  int count = 0;
  for (const Block& b : program.blocks) {
    if (b.stmt.gotoBlock &&
        &program.blocks[static_cast<std::size_t>(*b.stmt.gotoBlock)] ==
            &target) {
      ++count;
    }
  }
  return count;
}

/// What `#3000 = n (MESSAGE)` raises: the alarm the control shows.
std::string macroAlarmRaised(const Stmt& s) {
  const std::string_view message = trimmedMessage(s.message);
  const std::string shown(message.substr(0, kMessageShown));
  const std::string cut =
      message.size() > kMessageShown
          ? fmt::format(" (the control shows the first {} characters)",
                        kMessageShown)
          : "";
  const std::optional<double> value = constantOf(s.value.get());
  if (!value) {
    return fmt::format("\n\nHere: alarm {} + the value (0 to {}), `{}`{}; "
                       "the run stops at this block.",
                       kMacroAlarmVariable, kMacroAlarmLast, shown, cut);
  }
  const double n = roundHalfAway(*value);
  if (n < 0 || n > kMacroAlarmLast) {
    return fmt::format("\n\nHere: {} is not 0 to {}, so the block raises "
                       "{} instead.",
                       *value, kMacroAlarmLast,
                       alarmCode(AlarmId::ArgumentOutOfRange, 0));
  }
  return fmt::format("\n\nHere: alarm **{}** `{}`{}; the run stops at this "
                     "block.",
                     kMacroAlarmVariable + static_cast<int>(n), shown, cut);
}

} // namespace

std::optional<Hover> hoverAt(const Found& found, const Unit& unit,
                             std::string_view text, char latheSystem) {
  if (found.onSequence) {
    const int jumps = jumpsTo(*found.program, *found.block);
    return Hover{fmt::format("**N{}**: sequence number of {}{}",
                             found.block->seq, found.program->name,
                             jumps == 0
                                 ? std::string()
                                 : fmt::format("; {} GOTO{} to it", jumps,
                                               jumps == 1 ? "" : "s")),
                 sequenceRange(*found.block, text)};
  }
  if (const std::optional<VariableAt> v = variableAt(found)) {
    std::string markdown = variableHover(v->number);
    if (isLocal(v->number) && found.program != nullptr) {
      markdown += passedBy(unit, *found.program, v->number);
    }
    if (found.onTarget && v->number == kMacroAlarmVariable) {
      markdown += macroAlarmRaised(found.block->stmt);
    }
    return Hover{markdown, v->range};
  }
  const Expr* e = found.expr;
  if (e != nullptr && e->kind == ExprKind::Call) {
    return Hover{fmt::format("**{}**: a function of Custom Macro B",
                             builtinName(e->builtin)),
                 e->range};
  }
  const Word* w = found.word;
  if (w != nullptr && w->value && w->value->kind == ExprKind::Number) {
    const std::string_view written =
        text.substr(w->range.begin.offset, w->range.length);
    if (w->letter == 'G') {
      return Hover{gCodeHover(written, w->value->number, latheSystem),
                   w->range};
    }
    if (w->letter == 'M') {
      return Hover{mCodeHover(written, w->value->number), w->range};
    }
  }
  return std::nullopt;
}

} // namespace mbc::lsp
