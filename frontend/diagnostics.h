// Diagnostics: the engine collects messages by kind (diagnostic_kinds.def),
// with notes and fix-its; the printer renders them clang-style.
#pragma once

#include "frontend/source.h"
#include <mbc/alarm.h>

#include <fmt/format.h>

#include <deque>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mbc {

enum class DiagKind {
#define DIAG(Id, Severity, Alarm, Text) Id,
#define WARNING(Id, Flag, Text) Id,
#include "frontend/diagnostic_kinds.def"
};

enum class Severity { Error, Warning, Note };

struct FixIt {
  SourceRange range; // text to replace (length 0: insert at range.begin)
  std::string replacement;
};

struct Diagnostic {
  DiagKind kind;
  Severity severity;
  SourceRange range;
  std::string message;
  std::vector<FixIt> fixIts;
  std::vector<Diagnostic> notes;
  // What `mbc run` makes of an error (runTimeAlarm, unless the parser
  // chose better for the block's statement).
  AlarmId alarm = AlarmId::None;
};

Severity severityOf(DiagKind kind);

/// The kind's name in diagnostic_kinds.def ("ExpectedExpression"): the
/// rule of machine-readable diagnostics.
const char* kindName(DiagKind kind);
/// "error", "warning" or "note", as diagnostics print it.
const char* severityText(Severity severity);
/// The alarm a block with this error raises when it runs (AlarmId::None:
/// the run goes on).
AlarmId runTimeAlarm(DiagKind kind);
const char* formatOf(DiagKind kind);

/// A warning's flag ("missing-program": -Wno-missing-program hides it),
/// nullptr for errors and notes.
const char* warningFlag(DiagKind kind);
/// The warning a flag names.
std::optional<DiagKind> warningNamed(std::string_view flag);
/// Every warning's flag, in the order of diagnostic_kinds.def.
std::vector<std::string_view> warningFlags();

class DiagnosticEngine {
public:
  explicit DiagnosticEngine(const SourceManager& sources) : sources_(sources) {}

  template <typename... Args>
  Diagnostic& report(DiagKind kind, SourceRange range, const Args&... args) {
    return add(kind, range,
               fmt::vformat(formatOf(kind), fmt::make_format_args(args...)));
  }

  /// Attaches a note to the last diagnostic reported.
  template <typename... Args>
  void note(DiagKind kind, SourceRange range, const Args&... args) {
    // Not diags_.back(): "too many errors" follows the last error that
    // fits, and an error past the limit is not stored at all.
    if (lastStored_ < 0) {
      return;
    }
    diags_[static_cast<std::size_t>(lastStored_)].notes.push_back(
        Diagnostic{kind,
                   Severity::Note,
                   range,
                   fmt::vformat(formatOf(kind), fmt::make_format_args(args...)),
                   {},
                   {}});
  }

  int errorCount() const { return errors_; }

  /// Every error reported, those past the limit too.
  int totalErrors() const { return totalErrors_; }

  /// The first error with a run-time alarm reported since the last call,
  /// which the parser makes the alarm of the block it was reading; kind is
  /// nullopt when there was none.
  struct BlockError {
    std::optional<DiagKind> kind;
    std::string message;
    int index = -1; // in diagnostics(), -1 past the error limit
  };

  BlockError takeBlockError() { return std::exchange(blockError_, {}); }

  /// The alarm a block raises for its error, when the parser knows better
  /// than the table (a macro statement's format error).
  void setAlarm(const BlockError& error, AlarmId alarm) {
    if (error.index >= 0) {
      diags_[static_cast<std::size_t>(error.index)].alarm = alarm;
    }
  }

  int warningCount() const { return warnings_; }

  bool tooManyErrors() const { return errors_ >= kErrorLimit; }

  const std::deque<Diagnostic>& diagnostics() const { return diags_; }

  const SourceManager& sources() const { return sources_; }

  static constexpr int kErrorLimit = 50;

private:
  Diagnostic& add(DiagKind kind, SourceRange range, std::string message);

  const SourceManager& sources_;
  // A deque: the reference report() returns stays valid while more
  // diagnostics are reported (a parser adds fix-its after parsing on).
  std::deque<Diagnostic> diags_;
  Diagnostic overflow_{};
  int lastStored_ = -1; // diags_ index of the last report, -1 if dropped
  int errors_ = 0;
  int totalErrors_ = 0;
  int warnings_ = 0;
  BlockError blockError_;
};

/// A diagnostic's message as the detail of its run-time alarm: without the
/// " (PS0124)" that names the alarm the report shows anyway.
std::string alarmDetail(std::string_view message);

/// What an error is to the command that reads the input.
enum class ErrorMode {
  Refuse, // mbc check, --strict: errors are errors
  Alarm,  // mbc run: errors are warnings, their blocks alarm when they run
};

/// What the command line makes of warnings.
enum class WarningMode {
  Show,
  Hide,  // -w
  Error, // -Werror: each warning is an error, the input is refused
};

/// How the diagnostics are shown: the same ones in every format.
struct DiagnosticView {
  ErrorMode errors = ErrorMode::Refuse;
  WarningMode warnings = WarningMode::Show;
  std::set<DiagKind> disabled; // -Wno-flag: warnings not shown
};

/// A diagnostic as the reader gets it.
struct ShownDiagnostic {
  const Diagnostic* diagnostic;
  Severity severity;        // after the modes
  bool fromWarning = false; // an error made of a warning by -Werror
  /// Under ErrorMode::Alarm, the alarm an error's block raises when it runs
  /// (the error is then shown as a warning).
  AlarmId alarm = AlarmId::None;
};

/// The option that shows a warning, as clang names it after the message:
/// "-Wflag", or "-Werror,-Wflag" once -Werror made it an error; "" for
/// errors and notes.
std::string warningOption(const ShownDiagnostic& shown);

/// The diagnostics to show, in file order (parsing and the semantic checks
/// report in two passes), "too many errors" last.
std::vector<ShownDiagnostic> shownDiagnostics(const DiagnosticEngine& engine,
                                              const DiagnosticView& view);

/// The number of errors the view makes: the engine's, plus the warnings
/// under WarningMode::Error.
int shownErrorCount(const DiagnosticEngine& engine, const DiagnosticView& view);

/// clang-style text of every diagnostic: "file:line:col: error: message",
/// the source line, a caret under the range, and fix-it lines; in clang's
/// colours when `color`. Under ErrorMode::Alarm an error prints as a warning
/// with a note naming the alarm its block raises.
std::string renderDiagnostics(const DiagnosticEngine& engine,
                              const DiagnosticView& view, bool color = false);

inline std::string renderDiagnostics(const DiagnosticEngine& engine,
                                     ErrorMode mode = ErrorMode::Refuse) {
  return renderDiagnostics(engine, DiagnosticView{mode, WarningMode::Show, {}});
}

} // namespace mbc
