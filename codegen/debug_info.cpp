// DWARF for `-g` (see debug_info.h): a C compile unit, so that debuggers
// that know nothing about Macro B still show its files and lines.
#include "codegen/debug_info.h"

#include <llvm/BinaryFormat/Dwarf.h>
#include <llvm/IR/DebugInfoMetadata.h>

#include <filesystem>
#include <system_error>

namespace mbc::codegen {

DebugInfo::DebugInfo(llvm::Module& module, const ir::Module& ir)
    : builder_(module) {
  // The first source names the unit, as a C compiler's main file would.
  llvm::DIFile* main = file(ir.functions.empty() ? module.getName().str()
                                                 : ir.functions[0].file);
  unit_ = builder_.createCompileUnit(llvm::dwarf::DW_LANG_C, main, "mbc", false,
                                     "", 0);
  type_ = builder_.createSubroutineType(builder_.getOrCreateTypeArray({}));
  module.addModuleFlag(llvm::Module::Warning, "Debug Info Version",
                       llvm::DEBUG_METADATA_VERSION);
  module.addModuleFlag(llvm::Module::Max, "Dwarf Version", 4);
}

// Relative names stay as given, against the working directory, as a C
// compiler records them: the debugger then shows what the user typed.
llvm::DIFile* DebugInfo::file(const std::string& path) {
  auto it = files_.find(path);
  if (it != files_.end()) {
    return it->second;
  }
  std::filesystem::path p(path.empty() ? "<unknown>" : path);
  std::string directory;
  std::string name = p.string();
  if (p.is_absolute()) {
    directory = p.parent_path().string();
    name = p.filename().string();
  } else {
    std::error_code ec;
    directory = std::filesystem::current_path(ec).string();
  }
  llvm::DIFile* f = builder_.createFile(name, directory);
  files_.emplace(path, f);
  return f;
}

std::uint32_t DebugInfo::firstLine(const ir::Function& f) {
  for (const ir::Block& block : f.blocks) {
    for (ir::ValueId id : block.insts) {
      const ir::Inst& inst = f.insts[id];
      if (inst.op == ir::Op::Begin && inst.get<ir::SourceLine>().line > 0) {
        return inst.get<ir::SourceLine>().line;
      }
    }
  }
  return 1;
}

llvm::DISubprogram* DebugInfo::define(llvm::Function* fn,
                                      const std::string& name, llvm::DIFile* f,
                                      std::uint32_t line,
                                      llvm::DINode::DIFlags flags) {
  llvm::DISubprogram::DISPFlags spFlags = llvm::DISubprogram::SPFlagDefinition;
  if (fn->hasLocalLinkage()) {
    spFlags |= llvm::DISubprogram::SPFlagLocalToUnit;
  }
  llvm::DISubprogram* sp =
      builder_.createFunction(f, name, fn->getName(), f, line, type_, line,
                              flags | llvm::DINode::FlagPrototyped, spFlags);
  fn->setSubprogram(sp);
  return sp;
}

llvm::DISubprogram* DebugInfo::subprogram(llvm::Function* fn,
                                          const ir::Function& f) {
  return define(fn, f.name, file(f.file), firstLine(f), llvm::DINode::FlagZero);
}

llvm::DISubprogram* DebugInfo::artificial(llvm::Function* fn,
                                          const ir::Function* program) {
  return define(fn, fn->getName().str(),
                program != nullptr ? file(program->file) : unit_->getFile(),
                program != nullptr ? firstLine(*program) : 0,
                llvm::DINode::FlagArtificial);
}

llvm::DebugLoc DebugInfo::location(std::uint32_t line, llvm::DIScope* scope) {
  return llvm::DILocation::get(scope->getContext(), line, 0, scope);
}

void DebugInfo::finalize() {
  builder_.finalize();
}

} // namespace mbc::codegen
