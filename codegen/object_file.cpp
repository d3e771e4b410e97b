// LLVM IR, assembly and objects on disk (see object_file.h).
#include "codegen/object_file.h"

#include "codegen/abi.h"
#include "codegen/native_target.h"
#include "codegen/optimize.h"
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

#include <cstdio>

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

} // namespace

bool writeCompiled(const ir::Module& module, const ObjectOptions& options,
                   FileKind kind, const std::string& path, std::string& error) {
  std::unique_ptr<llvm::TargetMachine> tm = hostTarget(options, error);
  if (!tm) {
    return false;
  }
  auto context = makeContext();
  std::unique_ptr<llvm::Module> m = emitModule(module, *context, options.emit);
  m->setDataLayout(tm->createDataLayout());
  m->setTargetTriple(tm->getTargetTriple().str());
  if (!verifyEmitted(*m, error)) {
    return false;
  }
  optimize(*m, *tm, options.optLevel);
  tm->setOptLevel(codeGenLevel(options.optLevel, *m));
  if (path == "-") {
    llvm::raw_fd_ostream& out = llvm::outs();
    return emitTo(*m, *tm, kind, out, error);
  }
  std::string tmp = path + ".tmp";
  std::error_code ec;
  {
    llvm::raw_fd_ostream out(tmp, ec, llvm::sys::fs::OF_None);
    if (ec || !emitTo(*m, *tm, kind, out, error)) {
      if (ec) {
        error = "cannot write '" + tmp + "': " + ec.message();
      }
      std::remove(tmp.c_str());
      return false;
    }
    out.close();
    if (out.has_error()) {
      error = "cannot write '" + tmp + "': " + out.error().message();
      out.clear_error();
      std::remove(tmp.c_str());
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    error = "cannot replace '" + path + "'";
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

} // namespace mbc::codegen
