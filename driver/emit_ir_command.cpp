// `mbc emit-ir` and the module of the input (emit_ir_command.h).
#include "driver/emit_ir_command.h"

#include "ir/ir_parser.h"
#include "ir/printer.h"
#include <mbc/read_file.h>

#include <cstdio>
#include <cstring>

#include "toolchain/ir_pipeline.h"

namespace mbc::driver {

namespace {

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
  return toolchain::verifyModule(out, "error: invalid IR");
}

} // namespace

bool loadModule(const Options& o, ir::Module& out) {
  const toolchain::Request request = toolchainRequest(o);
  if (o.language == "mbir") {
    if (!parseIrFile(o.files, out)) {
      return false;
    }
  } else {
    toolchain::CompiledUnit cu;
    if (!toolchain::loadUnit(o.files, request.load, cu) ||
        !toolchain::buildModule(cu, request.trace, out)) {
      return false;
    }
  }
  return toolchain::optimizeModule(out, request.passes);
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
