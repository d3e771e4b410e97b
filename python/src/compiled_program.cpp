#include "compiled_program.h"

#include "frontend/diagnostics.h"

#include "toolchain/request.h"

namespace py = pybind11;

namespace mbc::python {

namespace {

py::dict place(const SourceManager& sources, SourceRange range) {
  const LineCol at = sources.lineCol(range.begin);
  py::dict d;
  d["file"] = sources.name(range.begin.file);
  d["line"] = at.line;
  d["column"] = at.col;
  return d;
}

py::dict diagnosticData(const SourceManager& sources, const Diagnostic& diag) {
  py::dict d = place(sources, diag.range);
  d["severity"] = severityText(diag.severity);
  d["message"] = diag.message;
  py::list fixits;
  for (const FixIt& fix : diag.fixIts) {
    py::dict f = place(sources, fix.range);
    f["length"] = fix.range.length;
    f["replacement"] = fix.replacement;
    fixits.append(f);
  }
  d["fixits"] = fixits;
  py::list notes;
  for (const Diagnostic& note : diag.notes) {
    notes.append(diagnosticData(sources, note));
  }
  d["notes"] = notes;
  return d;
}

} // namespace

std::unique_ptr<CompiledProgram>
CompiledProgram::compile(const CompileRequest& request, py::list& diagnostics,
                         std::string& message) {
  auto compiled = std::make_unique<CompiledProgram>();
  toolchain::Request r;
  r.files = request.files;
  r.load.errors = request.strict ? ErrorMode::Refuse : ErrorMode::Alarm;
  r.load.includeDirs = request.includeDirs;
  r.load.defaultMachine = request.defaultMachine;
  r.engine = toolchain::Engine::Jit;
  r.mainProgram = request.main;
  r.code.optLevel = request.opt;
  r.useCache = request.cache;
  const toolchain::LoadOptions& load = r.load;
  toolchain::PreparedProgram& prepared = compiled->prepared_;
  DiagnosticEngine diags(prepared.sources());
  if (!prepared.parse(request.texts, request.files, load, diags, message)) {
    return nullptr;
  }
  for (const Diagnostic& diag : diags.diagnostics()) {
    diagnostics.append(diagnosticData(prepared.sources(), diag));
  }
  if (load.errors == ErrorMode::Refuse && diags.errorCount() > 0) {
    message = renderDiagnostics(diags, load.errors);
    return nullptr;
  }
  runner::PhaseTimes phases;
  if (prepared.build(r, phases, message) != 0) {
    return nullptr;
  }
  return compiled;
}

py::list CompiledProgram::programs() const {
  py::list list;
  for (const Program& p : prepared_.unit().programs) {
    list.append(py::make_tuple(p.name, p.number));
  }
  return list;
}

} // namespace mbc::python
