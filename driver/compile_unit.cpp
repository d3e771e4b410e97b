// Reads the input files, parses and checks them, and prints diagnostics.
#include "driver/compile_unit.h"

#include "frontend/parser.h"
#include "frontend/sema.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace mbc::driver {

bool loadUnit(const std::vector<std::string>& files, bool checkWarnings,
              CompiledUnit& out, const std::string& machinePath) {
  DiagnosticEngine diags(out.sources);
  ParseOptions options;
  options.checkWarnings = checkWarnings;
  for (const std::string& path : files) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "mbc: error: cannot read '%s'\n", path.c_str());
      return false;
    }
    std::ostringstream text;
    text << in.rdbuf();
    std::uint32_t id = out.sources.add(path, text.str());
    parseFile(out.sources, id, diags, options, out.unit);
  }
  checkUnit(out.unit, diags, SemaOptions{machinePath.empty()});
  std::string rendered = renderDiagnostics(diags);
  std::fputs(rendered.c_str(), stderr);
  if (diags.errorCount() > 0) {
    std::fprintf(stderr, "%d error%s generated.\n", diags.errorCount(),
                 diags.errorCount() == 1 ? "" : "s");
    return false;
  }
  return true;
}

} // namespace mbc::driver
