// Reads the input files, parses and checks them, and prints diagnostics.
#include "driver/compile_unit.h"

#include "frontend/parser.h"
#include "frontend/sema.h"
#include <mbc/read_file.h>

#include <cstdio>
#include <cstring>
#include <utility>

namespace mbc::driver {

bool loadUnit(const std::vector<std::string>& files, bool checkWarnings,
              CompiledUnit& out, const std::string& machinePath,
              ErrorMode errors) {
  DiagnosticEngine diags(out.sources);
  ParseOptions options;
  options.checkWarnings = checkWarnings;
  options.stopAtErrorLimit = errors == ErrorMode::Refuse;
  for (const std::string& path : files) {
    std::string text;
    if (int error = readFile(path, text)) {
      std::fprintf(stderr, "mbc: error: cannot read '%s': %s\n", path.c_str(),
                   std::strerror(error));
      return false;
    }
    std::uint32_t id = out.sources.add(path, std::move(text));
    parseFile(out.sources, id, diags, options, out.unit);
  }
  checkUnit(out.unit, diags, SemaOptions{machinePath.empty()});
  std::string rendered = renderDiagnostics(diags, errors);
  std::fputs(rendered.c_str(), stderr);
  if (errors == ErrorMode::Alarm && diags.totalErrors() > 0) {
    std::fprintf(stderr,
                 "mbc: warning: %d error%s in the input: each block that has "
                 "one raises its alarm if the run reaches it (--strict "
                 "refuses the input)\n",
                 diags.totalErrors(), diags.totalErrors() == 1 ? "" : "s");
    return true;
  }
  if (diags.errorCount() > 0) {
    std::fprintf(stderr, "%d error%s generated.\n", diags.errorCount(),
                 diags.errorCount() == 1 ? "" : "s");
    return false;
  }
  return true;
}

} // namespace mbc::driver
