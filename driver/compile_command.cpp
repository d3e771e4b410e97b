// `mbc compile` and `mbc build` (see compile_command.h). build links the
// object with the run support and the runtime, compile --shared with the
// runtime (static libraries, own_libraries.h), by the system C++ compiler
// driver ($CXX, default c++).
#include "driver/compile_command.h"

#include "codegen/c_header.h"
#include "driver/emit_ir_command.h"
#include "ir/printer.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <unistd.h>

#include "build_paths.h" // MBC_SANITIZE
#include "runner/output_files.h"
#include "toolchain/code_generator.h"
#include "toolchain/own_libraries.h"
#include "toolchain/run_process.h"

namespace mbc::driver {

namespace {

// "out/cycle.o" -> "cycle": letters, digits and '_' of the file's stem.
std::string identifierStem(const std::string& path) {
  std::string stem = std::filesystem::path(path).stem().string();
  std::string id;
  for (char c : stem) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
              (c >= '0' && c <= '9');
    id += ok ? c : '_';
  }
  return id;
}

codegen::FileKind fileKind(const std::string& emit) {
  if (emit == "llvm") {
    return codegen::FileKind::LlvmIr;
  }
  return emit == "asm" ? codegen::FileKind::Assembly
                       : codegen::FileKind::Object;
}

int reportFailure(const std::string& error) {
  std::fprintf(stderr, "mbc: error: %s\n", error.c_str());
  return 4;
}

/// What is linked with the object, given its path and the scratch
/// directory it is in; empty when they could not be prepared.
using LinkInputs = std::function<std::vector<std::string>(
    const std::string& object, const std::string& dir)>;

/// Compiles the module to an object in a scratch directory and links it by
/// the system C++ compiler driver ($CXX, default c++) into o.outputPath,
/// through a temporary file so that a failed link leaves no half output.
/// -v shows the link command.
int compileAndLink(const ir::Module& module, const codegen::ObjectOptions& opts,
                   const Options& o, const LinkInputs& inputs) {
  std::string dir =
      (std::filesystem::temp_directory_path() / "mbc-link-XXXXXX").string();
  if (mkdtemp(dir.data()) == nullptr) {
    return reportFailure("cannot create a temporary directory");
  }
  const std::string object = dir + "/program.o";
  std::string error;
  std::vector<std::string> link;
  int status = 0;
  if (!toolchain::writeCompiled(module, opts, codegen::FileKind::Object, object,
                                error)) {
    status = reportFailure(error);
  } else if (link = inputs(object, dir); link.empty()) {
    status = reportFailure("cannot write the linker's inputs in " + dir);
  } else {
    const char* cxx = std::getenv("CXX");
    const std::string tmp = o.outputPath + ".tmp";
    link.insert(link.begin(),
                {cxx != nullptr && *cxx ? cxx : "c++", "-o", tmp});
    link.insert(link.end(), {"-lfmt", "-lm"});
    if (*MBC_SANITIZE != '\0') {
      // A runtime built with sanitizers links only with their libraries.
      link.push_back(std::string("-fsanitize=") + MBC_SANITIZE);
    }
    if (o.verbose) {
      std::fprintf(stderr, "%s\n",
                   fmt::format("{}", fmt::join(link, " ")).c_str());
    }
    const int linked = toolchain::runProcess(link);
    if (linked != 0) {
      std::remove(tmp.c_str());
      status = reportFailure(
          linked < 0 ? fmt::format("cannot run the linker '{}'", link[0])
                     : fmt::format("linking '{}' failed ({} exited with {})",
                                   o.outputPath, link[0], linked));
    } else if (std::rename(tmp.c_str(), o.outputPath.c_str()) != 0) {
      std::remove(tmp.c_str());
      status = reportFailure("cannot replace '" + o.outputPath + "'");
    }
  }
  std::filesystem::remove_all(dir);
  return status;
}

} // namespace

int compileCommand(const Options& o) {
  ir::Module module;
  if (!loadModule(o, module)) {
    return 1;
  }
  std::string table = o.tableName;
  if (table.empty()) {
    table = o.outputPath == "-"
                ? "mbc_programs"
                : "mbc_programs_" + identifierStem(o.outputPath);
  }
  codegen::ObjectOptions opts =
      toolchain::objectOptions(toolchainRequest(o).code, o.cpu);
  opts.emit.tableName = table;
  int status = 0;
  if (o.shared) {
    // The whole runtime goes in, since a ctypes user calls any of it; only
    // the C ABI is exported, so that the runtime's C++ symbols cannot clash
    // with the host process's.
    const std::string runtime = toolchain::ownLibraries().runtime;
    status = compileAndLink(
        module, opts, o,
        [&](const std::string& object, const std::string& dir) {
          const std::string script = dir + "/exports.map";
          if (!runner::replaceFile(script,
                                   fmt::format("{{ global: mbrt_*; mbc_O*; "
                                               "{}; local: *; }};\n",
                                               table))) {
            return std::vector<std::string>{};
          }
          return std::vector<std::string>{"-shared",
                                          object,
                                          "-Wl,--whole-archive",
                                          runtime,
                                          "-Wl,--no-whole-archive",
                                          "-Wl,--version-script=" + script};
        });
  } else if (o.emit == "ir") {
    if (!runner::replaceFile(o.outputPath, ir::print(module))) {
      status = reportFailure("cannot write '" + o.outputPath + "'");
    }
  } else {
    std::string error;
    if (!toolchain::writeCompiled(module, opts, fileKind(o.emit), o.outputPath,
                                  error)) {
      status = reportFailure(error);
    }
  }
  if (status == 0 && !o.headerPath.empty()) {
    std::string guard = "MBC_" + identifierStem(o.headerPath) + "_H";
    for (char& c : guard) {
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    if (!runner::replaceFile(o.headerPath,
                             codegen::cHeader(module, table, guard))) {
      return reportFailure("cannot write '" + o.headerPath + "'");
    }
  }
  return status;
}

int buildCommand(const Options& options) {
  // The executable takes --trace like `mbc run`: its code has the trace
  // statements, which cost a test each while no trace sink is set.
  Options o = options;
  o.run.trace = true;
  ir::Module module;
  if (!loadModule(o, module)) {
    return 1;
  }
  codegen::ObjectOptions opts =
      toolchain::objectOptions(toolchainRequest(o).code, o.cpu);
  opts.emit.entryPoints = false;
  opts.emit.aotMain = true;
  const toolchain::OwnLibraries& libs = toolchain::ownLibraries();
  return compileAndLink(
      module, opts, o, [&](const std::string& object, const std::string&) {
        return std::vector<std::string>{object, libs.runner, libs.runtime};
      });
}

} // namespace mbc::driver
