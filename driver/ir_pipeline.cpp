// Lowering, verification and the passes, and the emit-ir command.
#include "driver/ir_pipeline.h"

#include "ir/ir_parser.h"
#include "ir/lower.h"
#include "ir/pass_manager.h"
#include "ir/printer.h"
#include "ir/verifier.h"
#include <mbc/read_file.h>

#include <cstdio>
#include <cstring>

namespace mbc::driver {

namespace {

// Debug builds verify after every pass even without --verify-each.
#ifdef NDEBUG
constexpr bool kVerifyEachByDefault = false;
#else
constexpr bool kVerifyEachByDefault = true;
#endif

bool reportProblems(const std::vector<std::string>& problems,
                    const char* what) {
  for (const std::string& p : problems) {
    std::fprintf(stderr, "mbc: %s: %s\n", what, p.c_str());
  }
  return problems.empty();
}

// `-x mbir`: one file of IR text, which must be valid IR (it is input, so
// a problem is the user's error, not an internal one).
bool parseIrFile(const std::vector<std::string>& files, ir::Module& out) {
  if (files.size() != 1) {
    std::fprintf(stderr, "mbc: error: -x mbir takes exactly one file\n");
    return false;
  }
  std::string text;
  if (int error = readFile(files[0], text)) {
    std::fprintf(stderr, "mbc: error: cannot read '%s': %s\n", files[0].c_str(),
                 std::strerror(error));
    return false;
  }
  std::string error;
  if (!ir::parseModule(text, out, error)) {
    std::fprintf(stderr, "mbc: error: %s:%s\n", files[0].c_str(),
                 error.c_str());
    return false;
  }
  return reportProblems(ir::verify(out), "error: invalid IR");
}

} // namespace

bool buildModule(const CompiledUnit& cu, const Options& o, ir::Module& out) {
  out = ir::lower(cu.unit, cu.sources, ir::LowerOptions{o.run.trace});
  return reportProblems(ir::verify(out), "internal error: invalid IR");
}

bool optimizeModule(ir::Module& m, const Options& o) {
  if (o.noOpt) {
    return true;
  }
  ir::PassOptions po{o.disabledPasses, o.verifyEach || kVerifyEachByDefault};
  std::string error;
  if (!ir::runPasses(m, po, error)) {
    std::fprintf(stderr, "mbc: internal error: %s\n", error.c_str());
    return false;
  }
  return reportProblems(ir::verify(m),
                        "internal error: invalid IR after the passes");
}

bool loadModule(const Options& o, ir::Module& out) {
  if (o.language == "mbir") {
    if (!parseIrFile(o.files, out)) {
      return false;
    }
  } else {
    CompiledUnit cu;
    if (!loadUnit(o.files, loadOptions(o), cu) || !buildModule(cu, o, out)) {
      return false;
    }
  }
  return optimizeModule(out, o);
}

int emitIrCommand(const Options& o) {
  ir::Module module;
  if (!loadModule(o, module)) {
    return 1;
  }
  std::string text = ir::print(module);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

} // namespace mbc::driver
