#include "toolchain/diagnostic_formats.h"

#include "frontend/utf8.h"
#include <mbc/version.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <map>

namespace mbc::toolchain {

namespace {

using nlohmann::json;

struct Position {
  std::string file;
  int line = 0;
  int column = 0; // bytes, 1-based
  int codePointColumn = 0;
};

// The column in code points too (SARIF's columnKind): a byte that is no
// part of a valid UTF-8 character counts as one, as does each byte of the
// line's end.
Position position(const SourceManager& sm, SourceLoc loc) {
  const LineCol lc = sm.lineCol(loc);
  const std::string_view line = sm.lineText(loc);
  const auto before = static_cast<std::size_t>(lc.col - 1);
  int codePoints = 1;
  std::size_t i = 0;
  for (; i < before && i < line.size(); ++codePoints) {
    const std::size_t n = utf8Length(line, i);
    i += n == 0 ? 1 : n;
  }
  codePoints += static_cast<int>(before > i ? before - i : 0);
  return {sm.name(loc.file), lc.line, lc.col, codePoints};
}

SourceLoc endOf(SourceRange r) {
  return {r.begin.file, r.begin.offset + r.length};
}

json gccPosition(const Position& p) {
  return {{"file", p.file}, {"line", p.line}, {"column", p.column}};
}

json gccDiagnostic(const SourceManager& sm, const Diagnostic& d,
                   Severity severity) {
  json out = {{"kind", severityText(severity)},
              {"code", kindName(d.kind)},
              {"message", d.message}};
  json location = {{"caret", gccPosition(position(sm, d.range.begin))}};
  if (d.range.length > 1) {
    // GCC's finish is the range's last character.
    location["finish"] = gccPosition(position(
        sm, {d.range.begin.file, d.range.begin.offset + d.range.length - 1}));
  }
  out["locations"] = json::array({location});
  json fixits = json::array();
  for (const FixIt& f : d.fixIts) {
    fixits.push_back({{"start", gccPosition(position(sm, f.range.begin))},
                      {"next", gccPosition(position(sm, endOf(f.range)))},
                      {"string", f.replacement}});
  }
  if (!fixits.empty()) {
    out["fixits"] = fixits;
  }
  json children = json::array();
  for (const Diagnostic& n : d.notes) {
    children.push_back(gccDiagnostic(sm, n, Severity::Note));
  }
  if (!children.empty()) {
    out["children"] = children;
  }
  return out;
}

// A path as a URI reference: relative paths stay relative (to the
// directory mbc ran in), absolute ones become file: URIs.
std::string uriOf(const std::string& path) {
  std::string out = path.starts_with("/") ? "file://" : "";
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                       (c >= '0' && c <= '9') || c == '/' || c == '.' ||
                       c == '-' || c == '_' || c == '~';
    out += plain ? std::string(1, c) : fmt::format("%{:02X}", u);
  }
  return out;
}

// SARIF's end column is the one after the region; a range that ends with
// its line's end of line ends on that line.
json sarifRegion(const SourceManager& sm, SourceRange r) {
  const Position begin = position(sm, r.begin);
  Position end = position(sm, endOf(r));
  if (end.line > begin.line) {
    const std::string_view line = sm.lineText(r.begin);
    end = position(sm,
                   {r.begin.file, r.begin.offset - (begin.column - 1) +
                                      static_cast<std::uint32_t>(line.size())});
    end = end.codePointColumn < begin.codePointColumn ? begin : end;
  }
  return {{"startLine", begin.line},
          {"startColumn", begin.codePointColumn},
          {"endLine", end.line},
          {"endColumn", end.codePointColumn}};
}

json sarifLocation(const SourceManager& sm, SourceRange r) {
  return {{"physicalLocation",
           {{"artifactLocation", {{"uri", uriOf(sm.name(r.begin.file))}}},
            {"region", sarifRegion(sm, r)}}}};
}

} // namespace

std::string diagnosticsJson(const DiagnosticEngine& engine,
                            const DiagnosticView& view) {
  const SourceManager& sm = engine.sources();
  json out = json::array();
  for (const ShownDiagnostic& shown : shownDiagnostics(engine, view)) {
    const Diagnostic& d = *shown.diagnostic;
    if (d.kind == DiagKind::TooManyErrors) {
      out.push_back({{"kind", "error"},
                     {"code", kindName(d.kind)},
                     {"message", d.message},
                     {"locations", json::array()}});
      continue;
    }
    json one = gccDiagnostic(sm, d, shown.severity);
    if (const std::string option = warningOption(shown); !option.empty()) {
      one["option"] = option;
    }
    if (shown.alarm != AlarmId::None) {
      one["alarm"] = alarmCode(shown.alarm, 0);
    }
    out.push_back(one);
  }
  return out.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string diagnosticsSarif(const DiagnosticEngine& engine,
                             const DiagnosticView& view) {
  const SourceManager& sm = engine.sources();
  json rules = json::array();
  std::map<DiagKind, int> ruleIndex;
  json results = json::array();
  for (const ShownDiagnostic& shown : shownDiagnostics(engine, view)) {
    const Diagnostic& d = *shown.diagnostic;
    const auto [rule, added] =
        ruleIndex.emplace(d.kind, static_cast<int>(rules.size()));
    if (added) {
      rules.push_back({{"id", kindName(d.kind)},
                       {"defaultConfiguration",
                        {{"level", severityText(severityOf(d.kind))}}}});
    }
    json result = {{"ruleId", kindName(d.kind)},
                   {"ruleIndex", rule->second},
                   {"level", severityText(shown.severity)},
                   {"message", {{"text", d.message}}}};
    if (d.kind != DiagKind::TooManyErrors) {
      result["locations"] = json::array({sarifLocation(sm, d.range)});
    }
    json related = json::array();
    for (const Diagnostic& n : d.notes) {
      json note = sarifLocation(sm, n.range);
      note["message"] = {{"text", n.message}};
      related.push_back(note);
    }
    if (!related.empty()) {
      result["relatedLocations"] = related;
    }
    json fixes = json::array();
    for (const FixIt& f : d.fixIts) {
      fixes.push_back(
          {{"description",
            {{"text", f.replacement.empty()
                          ? std::string("remove the text")
                          : fmt::format("write '{}'", f.replacement)}}},
           {"artifactChanges",
            json::array(
                {{{"artifactLocation",
                   {{"uri", uriOf(sm.name(f.range.begin.file))}}},
                  {"replacements",
                   json::array({{{"deletedRegion", sarifRegion(sm, f.range)},
                                 {"insertedContent",
                                  {{"text", f.replacement}}}}})}}})}});
    }
    if (!fixes.empty()) {
      result["fixes"] = fixes;
    }
    json properties = json::object();
    if (const std::string option = warningOption(shown); !option.empty()) {
      properties["option"] = option;
    }
    if (shown.alarm != AlarmId::None) {
      properties["alarm"] = alarmCode(shown.alarm, 0);
    }
    if (!properties.empty()) {
      result["properties"] = properties;
    }
    results.push_back(result);
  }
  const json log = {
      {"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
      {"version", "2.1.0"},
      {"runs", json::array({{{"tool",
                              {{"driver",
                                {{"name", "mbc"},
                                 {"version", MBC_VERSION_STRING},
                                 {"rules", rules}}}}},
                             {"columnKind", "unicodeCodePoints"},
                             {"results", results}}})}};
  return log.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

} // namespace mbc::toolchain
