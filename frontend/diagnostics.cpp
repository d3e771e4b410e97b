// The diagnostic registry and the clang-style renderer.
#include "frontend/diagnostics.h"

#include "frontend/utf8.h"

#include <algorithm>
#include <array>
#include <tuple>

namespace mbc {

namespace {

struct KindRow {
  Severity severity;
  AlarmId alarm;
  const char* format;
};

constexpr std::array kKinds = {
#define DIAG(Id, Sev, Alarm, Text) KindRow{Severity::Sev, AlarmId::Alarm, Text},
#include "frontend/diagnostic_kinds.def"
};

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

void renderOne(const SourceManager& sm, const Diagnostic& d, std::string& out) {
  LineCol lc = sm.lineCol(d.range.begin);
  out += fmt::format("{}:{}:{}: {}: {}\n", sm.name(d.range.begin.file), lc.line,
                     lc.col, severityText(d.severity), d.message);
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
  out +=
      fmt::format("{}\n{}{}\n", shown.text, std::string(caretCol, ' '), marks);
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
    out += fix + "\n";
  }
  for (const Diagnostic& n : d.notes) {
    renderOne(sm, n, out);
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

Severity severityOf(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].severity;
}

AlarmId runTimeAlarm(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].alarm;
}

const char* formatOf(DiagKind kind) {
  return kKinds[static_cast<int>(kind)].format;
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

// Under ErrorMode::Alarm: the note that says what the run makes of an
// error, on one line (the error above shows the source).
std::string alarmNote(const SourceManager& sm, const Diagnostic& d) {
  const AlarmId alarm = d.alarm;
  if (alarm == AlarmId::None) {
    return "";
  }
  LineCol lc = sm.lineCol(d.range.begin);
  const bool jump =
      d.kind == DiagKind::GotoUndefined || d.kind == DiagKind::GotoRange;
  return fmt::format("{}:{}:{}: note: {} alarm {} {}{}\n",
                     sm.name(d.range.begin.file), lc.line, lc.col,
                     jump ? "the jump raises" : "this block raises",
                     alarmCode(alarm, 0), alarmInfo(alarm).message,
                     jump ? " when it is taken" : " when it runs");
}

std::string renderDiagnostics(const DiagnosticEngine& engine, ErrorMode mode) {
  // Parsing and the semantic checks report in two passes; the reader wants
  // file order.
  std::vector<const Diagnostic*> sorted;
  for (const Diagnostic& d : engine.diagnostics()) {
    sorted.push_back(&d);
  }
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const Diagnostic* a, const Diagnostic* b) {
                     auto key = [](const Diagnostic* d) {
                       return std::tuple(d->kind == DiagKind::TooManyErrors,
                                         d->range.begin.file,
                                         d->range.begin.offset);
                     };
                     return key(a) < key(b);
                   });
  std::string out;
  for (const Diagnostic* dp : sorted) {
    const Diagnostic& d = *dp;
    const bool alarms = mode == ErrorMode::Alarm;
    if (d.kind == DiagKind::TooManyErrors) {
      out += alarms ? "mbc: warning: too many problems; the others are not "
                      "shown\n"
                    : fmt::format("mbc: error: {}\n", d.message);
      continue;
    }
    if (alarms && d.severity == Severity::Error) {
      Diagnostic warning = d;
      warning.severity = Severity::Warning;
      renderOne(engine.sources(), warning, out);
      out += alarmNote(engine.sources(), d);
      continue;
    }
    renderOne(engine.sources(), d, out);
  }
  return out;
}

} // namespace mbc
