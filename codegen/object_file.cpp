// LLVM IR, assembly and objects on disk (see object_file.h).
#include "codegen/object_file.h"

#include "codegen/abi.h"
#include "codegen/emit_module.h"
#include "codegen/link_objects.h"
#include "codegen/native_target.h"
#include "codegen/optimize.h"
#include "codegen/out_of_memory.h"
#include "codegen/verify.h"

#include <llvm/ADT/Triple.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/MC/MCSubtargetInfo.h>
#include <llvm/MC/TargetRegistry.h>
#include <llvm/Support/FileSystem.h>
#include <llvm/Support/Host.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>
#include <llvm/Target/TargetOptions.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <numeric>
#include <thread>

namespace mbc::codegen {

namespace {

std::unique_ptr<llvm::TargetMachine> hostTarget(const ObjectOptions& o,
                                                std::string& error) {
  initializeNativeTarget();
  std::string triple = llvm::sys::getDefaultTargetTriple();
  const llvm::Target* target =
      llvm::TargetRegistry::lookupTarget(triple, error);
  if (target == nullptr) {
    return nullptr;
  }
  std::string cpu = o.cpu;
  std::string features;
  if (cpu == "native") {
    cpu = llvm::sys::getHostCPUName().str();
    llvm::StringMap<bool> host;
    if (llvm::sys::getHostCPUFeatures(host)) {
      for (const auto& f : host) {
        features += (features.empty() ? "" : ",") +
                    std::string(f.second ? "+" : "-") + f.first().str();
      }
    }
  } else if (!cpu.empty()) {
    std::unique_ptr<llvm::MCSubtargetInfo> sti(
        target->createMCSubtargetInfo(triple, "", ""));
    if (!sti || !sti->isCPUStringValid(cpu)) {
      error = "unknown CPU '" + cpu + "' for " + triple +
              " (try native, or a name llc -mcpu=help lists)";
      return nullptr;
    }
  } else {
    cpu = llvm::Triple(triple).getArch() == llvm::Triple::x86_64 ? "x86-64"
                                                                 : "generic";
  }
  std::unique_ptr<llvm::TargetMachine> tm(target->createTargetMachine(
      triple, cpu, features, llvm::TargetOptions(), llvm::Reloc::PIC_, {},
      llvm::CodeGenOpt::Default));
  if (!tm) {
    error = "cannot create a target machine for " + triple + " " + cpu;
  }
  return tm;
}

bool emitTo(llvm::Module& m, llvm::TargetMachine& tm, FileKind kind,
            llvm::raw_pwrite_stream& out, std::string& error) {
  if (kind == FileKind::LlvmIr) {
    m.print(out, nullptr);
    return true;
  }
  llvm::legacy::PassManager pm;
  auto type = kind == FileKind::Assembly ? llvm::CGFT_AssemblyFile
                                         : llvm::CGFT_ObjectFile;
  if (tm.addPassesToEmitFile(pm, out, nullptr, type)) {
    error = "the target cannot emit this kind of file";
    return false;
  }
  pm.run(m);
  return true;
}

// The emitted part of `module` (all of it unless `emit` selects) into `out`.
bool compileModule(const ir::Module& module, const ObjectOptions& options,
                   const EmitOptions& emit, FileKind kind,
                   llvm::raw_pwrite_stream& out, std::string& error) {
  std::unique_ptr<llvm::TargetMachine> tm = hostTarget(options, error);
  if (!tm) {
    return false;
  }
  auto context = makeContext();
  std::unique_ptr<llvm::Module> m = emitModule(module, *context, emit);
  m->setDataLayout(tm->createDataLayout());
  m->setTargetTriple(tm->getTargetTriple().str());
  if (!verifyEmitted(*m, error)) {
    return false;
  }
  optimize(*m, *tm, options.optLevel, options.sizeLevel);
  // Decided for the whole module, so that every part is compiled alike.
  tm->setOptLevel(hasUnoptimizedBody(module)
                      ? llvm::CodeGenOpt::None
                      : codeGenLevel(options.optLevel, *m));
  return emitTo(*m, *tm, kind, out, error);
}

bool writeFile(const std::string& path, std::string& error,
               const std::function<bool(llvm::raw_pwrite_stream&)>& write) {
  std::error_code ec;
  llvm::raw_fd_ostream out(path, ec, llvm::sys::fs::OF_None);
  if (ec) {
    error = "cannot write '" + path + "': " + ec.message();
    return false;
  }
  if (!write(out)) {
    return false;
  }
  out.close();
  if (out.has_error()) {
    error = "cannot write '" + path + "': " + out.error().message();
    out.clear_error();
    return false;
  }
  return true;
}

/// IR instructions from which an object is compiled in two parts at once:
/// below, a thread and `ld -r` cost more than they save.
constexpr std::size_t kPartsThreshold = 4000;

bool worthParts(const ir::Module& module) {
  std::size_t size = 0;
  for (const ir::Function& f : module.functions) {
    size += f.insts.size();
  }
  return size >= kPartsThreshold && module.functions.size() > 1 &&
         std::thread::hardware_concurrency() > 1;
}

// Two parts of about the same size, the biggest programs first.
std::vector<char> firstPart(const ir::Module& module) {
  std::vector<std::size_t> order(module.functions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) {
    return module.functions[a].insts.size() > module.functions[b].insts.size();
  });
  std::vector<char> first(order.size(), 0);
  std::size_t sizes[2] = {0, 0};
  for (std::size_t i : order) {
    int part = sizes[0] <= sizes[1] ? 0 : 1;
    first[i] = static_cast<char>(part == 0);
    sizes[part] += module.functions[i].insts.size();
  }
  return first;
}

// LLVM's time is spent per function, and the two halves of a module
// compile in their own contexts on two cores; `ld -r` makes them one
// object again.
bool compileInParts(const ir::Module& module, const ObjectOptions& options,
                    const std::string& path, std::string& error) {
  initializeNativeTarget();
  std::vector<EmitOptions> emits(2, options.emit);
  emits[0].bodiesHere = firstPart(module);
  emits[1].bodiesHere = emits[0].bodiesHere;
  for (char& here : emits[1].bodiesHere) {
    here = static_cast<char>(here == 0);
  }
  emits[1].home = false;
  std::vector<std::string> files = {path + ".0", path + ".1"};
  std::string errors[2];
  bool ok[2] = {false, false};
  auto compilePart = [&](int i) {
    ok[i] = writeFile(files[i], errors[i], [&](llvm::raw_pwrite_stream& out) {
      return compileModule(module, options, emits[i], FileKind::Object, out,
                           errors[i]);
    });
  };
  std::thread other(compilePart, 1);
  compilePart(0);
  other.join();
  bool linked = ok[0] && ok[1] && linkRelocatable(files, path, error);
  if (!ok[0] || !ok[1]) {
    error = errors[ok[0] ? 1 : 0];
  }
  for (const std::string& f : files) {
    std::remove(f.c_str());
  }
  return linked;
}

} // namespace

bool writeCompiled(const ir::Module& module, const ObjectOptions& options,
                   FileKind kind, const std::string& path, std::string& error) {
  ExitOnOutOfMemory exitOnOutOfMemory;
  auto compile = [&](llvm::raw_pwrite_stream& out) {
    return compileModule(module, options, options.emit, kind, out, error);
  };
  if (path == "-") {
    return compile(llvm::outs());
  }
  std::string tmp = path + ".tmp";
  // Without a linker to combine the parts, in one piece.
  bool written = kind == FileKind::Object && worthParts(module) &&
                 compileInParts(module, options, tmp, error);
  if (!written && !writeFile(tmp, error, compile)) {
    std::remove(tmp.c_str());
    return false;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    error = "cannot replace '" + path + "'";
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

} // namespace mbc::codegen
