// The diagnostics as data, for editors and code-scanning services: mbc's
// JSON (the shape of GCC's -fdiagnostics-format=json) and SARIF 2.1.0.
#pragma once

#include "frontend/diagnostics.h"

#include <set>
#include <string>

namespace mbc::toolchain {

enum class DiagnosticFormat { Text, Json, Sarif };

/// How the diagnostics of the input are printed (--diagnostics-format,
/// --color, -w, -Werror).
struct DiagnosticOutput {
  DiagnosticFormat format = DiagnosticFormat::Text;
  bool color = false;
  WarningMode warnings = WarningMode::Show;
  std::set<DiagKind> disabled; // -Wno-flag
};

/// One line: a JSON array with an object per diagnostic: "kind" (error,
/// warning, note), "code" (the kind's name), "message", "locations" (caret
/// and finish: file, line, column), "children" (its notes), "fixits"
/// (start, next, string), for a warning "option" (-Wflag, or
/// -Werror,-Wflag) and, under ErrorMode::Alarm, "alarm".
std::string diagnosticsJson(const DiagnosticEngine& engine,
                            const DiagnosticView& view);

/// One line: a SARIF 2.1.0 log with one run of mbc: a result per diagnostic
/// with its rule (the kind), level, location, notes as related locations
/// and fix-its as fixes.
std::string diagnosticsSarif(const DiagnosticEngine& engine,
                             const DiagnosticView& view);

} // namespace mbc::toolchain
