// The diagnostic registry and the clang-style renderer.
#include "frontend/diagnostics.h"

#include "frontend/utf8.h"

#include <algorithm>
#include <array>
#include <tuple>

namespace mbc {

namespace {

struct KindRow {
  const char* name;
  Severity severity;
  AlarmId alarm;
  const char* format;
  const char* flag; // a warning's -W flag, nullptr for the others
};

constexpr std::array kKinds = {
#define DIAG(Id, Sev, Alarm, Text)                                             \
  KindRow{#Id, Severity::Sev, AlarmId::Alarm, Text, nullptr},
#define WARNING(Id, Flag, Text)                                                \
  KindRow{#Id, Severity::Warning, AlarmId::None, Text, Flag},
#include "frontend/diagnostic_kinds.def"
};

/// Each flag names one kind of warning: -Wno-FLAG hides no other.
constexpr bool flagsAreUnique() {
  for (std::size_t i = 0; i < kKinds.size(); ++i) {
    for (std::size_t j = i + 1; j < kKinds.size() && kKinds[i].flag; ++j) {
      if (kKinds[j].flag && std::string_view(kKinds[i].flag) ==
                                std::string_view(kKinds[j].flag)) {
        return false;
      }
    }
  }
  return true;
}

static_assert(flagsAreUnique());

// The source line as shown under a diagnostic: control bytes and invalid
// UTF-8 escaped (a NUL must not cut the output), tabs as one space, and only
// a window around the caret of a very long line. column[i] is the display
// column of byte i (kHidden outside the window); column[size] ends the line.
struct ShownLine {
  static constexpr std::size_t kHidden = static_cast<std::size_t>(-1);
  std::string text;
  std::vector<std::size_t> column;
};

ShownLine showLine(std::string_view line, std::size_t focus) {
  constexpr std::size_t kMaxShown = 160, kBefore = 70;
  std::size_t first = 0, last = line.size();
  if (line.size() > kMaxShown) {
    first = focus > kBefore ? focus - kBefore : 0;
    // Back to the start of a character: at most three bytes, since a run of
    // stray continuation bytes is no character (the fuzzer's line of them
    // pushed the window past the caret).
    for (int k = 0; k < 3 && first > 0 &&
                    isContinuation(static_cast<unsigned char>(line[first]));
         ++k) {
      --first;
    }
    last = std::min(line.size(), first + kMaxShown);
  }
  ShownLine s;
  s.column.assign(line.size() + 1, ShownLine::kHidden);
  if (first > 0) {
    s.text = "...";
  }
  std::size_t width = s.text.size();
  for (std::size_t i = first; i < last;) {
    auto b = static_cast<unsigned char>(line[i]);
    s.column[i] = width;
    if (b >= 0x80) {
      if (std::size_t n = utf8Length(line, i)) {
        s.text.append(line.substr(i, n));
        for (std::size_t k = 1; k < n; ++k) {
          s.column[i + k] = width;
        }
        i += n;
        ++width;
        continue;
      }
    }
    if (b == '\t') {
      s.text += ' ';
      ++width;
    } else if (b < 0x20 || b >= 0x7F) {
      s.text += fmt::format("\\x{:02x}", b);
      width += 4;
    } else {
      s.text += static_cast<char>(b);
      ++width;
    }
    ++i;
  }
  s.column[last] = width;
  if (last < line.size()) {
    s.text += "...";
  }
  return s;
}

// clang's and gcc's colours: the location and message bold, the severity
// in its colour, the caret line bold green, fix-its green.
struct Style {
  bool color = false;

  std::string paint(const char* code, std::string_view text) const {
    return color ? fmt::format("\033[{}m{}\033[0m", code, text)
                 : std::string(text);
  }
};

const char* severityColor(Severity s) {
  switch (s) {
    case Severity::Error:
      return "1;31";
    case Severity::Warning:
      return "1;35";
    case Severity::Note:
      return "1;36";
  }
  return "1";
}

void renderOne(const SourceManager& sm, const Diagnostic& d, Severity severity,
               std::string_view suffix, const Style& style, std::string& out) {
  LineCol lc = sm.lineCol(d.range.begin);
  out += style.paint("1", fmt::format("{}:{}:{}:", sm.name(d.range.begin.file),
                                      lc.line, lc.col)) +
         " " +
         style.paint(severityColor(severity),
                     fmt::format("{}:", severityText(severity))) +
         " " + style.paint("1", fmt::format("{}{}", d.message, suffix)) + "\n";
  std::string_view line = sm.lineText(d.range.begin);
  auto at = std::min(static_cast<std::size_t>(lc.col - 1), line.size());
  ShownLine shown = showLine(line, at);
  std::size_t caretCol = shown.column[at];
  std::size_t endByte = std::min(line.size(), at + d.range.length);
  std::size_t endCol = shown.column[endByte] == ShownLine::kHidden
                           ? shown.text.size()
                           : shown.column[endByte];
  std::string marks = "^";
  if (endCol > caretCol + 1) {
    marks.append(endCol - caretCol - 1, '~');
  }
  out += fmt::format("{}\n{}{}\n", shown.text, std::string(caretCol, ' '),
                     style.paint("1;32", marks));
  // All fix-its of the line go on one line under the caret, clang-style.
  std::string fix;
  for (const FixIt& f : d.fixIts) {
    LineCol flc = sm.lineCol(f.range.begin);
    auto fat = std::min(static_cast<std::size_t>(flc.col - 1), line.size());
    if (flc.line != lc.line || shown.column[fat] == ShownLine::kHidden) {
      continue;
    }
    std::size_t col = shown.column[fat];
    if (fix.size() < col) {
      fix.append(col - fix.size(), ' ');
    }
    fix.replace(col, std::min(f.replacement.size(), fix.size() - col),
                f.replacement);
  }
  if (!fix.empty()) {
    const std::size_t indent = fix.find_first_not_of(' ');
    out +=
        fix.substr(0, indent) + style.paint("0;32", fix.substr(indent)) + "\n";
  }
  for (const Diagnostic& n : d.notes) {
    renderOne(sm, n, Severity::Note, "", style, out);
  }
}

} // namespace

const char* severityText(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

const char* kindName(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].name;
}

Severity severityOf(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].severity;
}

AlarmId runTimeAlarm(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].alarm;
}

const char* formatOf(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].format;
}

const char* warningFlag(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].flag;
}

std::optional<DiagKind> warningNamed(std::string_view flag) {
  for (std::size_t i = 0; i < kKinds.size(); ++i) {
    if (kKinds[i].flag != nullptr && flag == kKinds[i].flag) {
      return static_cast<DiagKind>(i);
    }
  }
  return std::nullopt;
}

std::vector<std::string_view> warningFlags() {
  std::vector<std::string_view> flags;
  for (const KindRow& row : kKinds) {
    if (row.flag != nullptr) {
      flags.emplace_back(row.flag);
    }
  }
  return flags;
}

std::string warningOption(const ShownDiagnostic& shown) {
  const char* flag = warningFlag(shown.diagnostic->kind);
  if (flag == nullptr) {
    return "";
  }
  return fmt::format("{}-W{}", shown.fromWarning ? "-Werror," : "", flag);
}

Diagnostic& DiagnosticEngine::add(DiagKind kind, SourceRange range,
                                  std::string message) {
  Severity sev = severityOf(kind);
  if (sev == Severity::Error) {
    ++totalErrors_;
    const bool blockError =
        !blockError_.kind && runTimeAlarm(kind) != AlarmId::None;
    if (blockError) {
      blockError_ = {kind, message, -1};
    }
    if (errors_ >= kErrorLimit) {
      lastStored_ = -1;
      // Past the limit nothing is stored; callers may still attach fix-its.
      overflow_ = Diagnostic{kind, sev, range, std::move(message), {}, {}};
      return overflow_;
    }
    ++errors_;
    if (blockError) {
      blockError_.index = static_cast<int>(diags_.size());
    }
  } else if (sev == Severity::Warning) {
    ++warnings_;
  }
  diags_.push_back(Diagnostic{
      kind, sev, range, std::move(message), {}, {}, runTimeAlarm(kind)});
  lastStored_ = static_cast<int>(diags_.size()) - 1;
  if (errors_ == kErrorLimit && sev == Severity::Error) {
    diags_.push_back(Diagnostic{DiagKind::TooManyErrors,
                                Severity::Error,
                                range,
                                formatOf(DiagKind::TooManyErrors),
                                {},
                                {}});
    return diags_[diags_.size() - 2];
  }
  return diags_.back();
}

std::string alarmDetail(std::string_view message) {
  constexpr std::string_view kPrefix = " (PS";
  const std::size_t at = message.rfind(kPrefix);
  if (at != std::string_view::npos && message.size() == at + 9 &&
      message.back() == ')') {
    message = message.substr(0, at);
  }
  return std::string(message);
}

namespace {

std::string alarmNote(const SourceManager& sm, const ShownDiagnostic& shown,
                      const Style& style) {
  const Diagnostic& d = *shown.diagnostic;
  LineCol lc = sm.lineCol(d.range.begin);
  const bool jump =
      d.kind == DiagKind::GotoUndefined || d.kind == DiagKind::GotoRange;
  return style.paint("1", fmt::format("{}:{}:{}:", sm.name(d.range.begin.file),
                                      lc.line, lc.col)) +
         " " + style.paint(severityColor(Severity::Note), "note:") + " " +
         style.paint(
             "1", fmt::format("{} alarm {} {}{}",
                              jump ? "the jump raises" : "this block raises",
                              alarmCode(shown.alarm, 0),
                              alarmInfo(shown.alarm).message,
                              jump ? " when it is taken" : " when it runs")) +
         "\n";
}

} // namespace

std::vector<ShownDiagnostic> shownDiagnostics(const DiagnosticEngine& engine,
                                              const DiagnosticView& view) {
  std::vector<ShownDiagnostic> shown;
  for (const Diagnostic& d : engine.diagnostics()) {
    ShownDiagnostic s{&d, d.severity};
    if (d.severity == Severity::Warning) {
      if (view.warnings == WarningMode::Hide ||
          view.disabled.contains(d.kind)) {
        continue;
      }
      s.fromWarning = view.warnings == WarningMode::Error;
      s.severity = s.fromWarning ? Severity::Error : Severity::Warning;
    } else if (d.severity == Severity::Error &&
               view.errors == ErrorMode::Alarm &&
               d.kind != DiagKind::TooManyErrors) {
      s.severity = Severity::Warning;
      s.alarm = d.alarm;
    }
    shown.push_back(s);
  }
  std::stable_sort(shown.begin(), shown.end(),
                   [](const ShownDiagnostic& a, const ShownDiagnostic& b) {
                     auto key = [](const Diagnostic* d) {
                       return std::tuple(d->kind == DiagKind::TooManyErrors,
                                         d->range.begin.file,
                                         d->range.begin.offset);
                     };
                     return key(a.diagnostic) < key(b.diagnostic);
                   });
  return shown;
}

int shownErrorCount(const DiagnosticEngine& engine,
                    const DiagnosticView& view) {
  if (view.warnings != WarningMode::Error) {
    return engine.errorCount();
  }
  const std::vector<ShownDiagnostic> shown = shownDiagnostics(engine, view);
  return engine.errorCount() +
         static_cast<int>(std::count_if(
             shown.begin(), shown.end(),
             [](const ShownDiagnostic& s) { return s.fromWarning; }));
}

std::string renderDiagnostics(const DiagnosticEngine& engine,
                              const DiagnosticView& view, bool color) {
  const Style style{color};
  const SourceManager& sm = engine.sources();
  std::string out;
  for (const ShownDiagnostic& shown : shownDiagnostics(engine, view)) {
    const Diagnostic& d = *shown.diagnostic;
    if (d.kind == DiagKind::TooManyErrors) {
      out += view.errors == ErrorMode::Alarm
                 ? "mbc: warning: too many problems; the others are not "
                   "shown\n"
                 : fmt::format("mbc: error: {}\n", d.message);
      continue;
    }
    const std::string option = warningOption(shown);
    renderOne(sm, d, shown.severity, option.empty() ? "" : " [" + option + "]",
              style, out);
    if (shown.alarm != AlarmId::None) {
      out += alarmNote(sm, shown, style);
    }
  }
  return out;
}

} // namespace mbc
