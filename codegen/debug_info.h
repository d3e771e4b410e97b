// DWARF for `-g`: the compile unit, files and subprograms that let a
// debugger map compiled Macro B code back to .nc source lines.
#pragma once

#include "ir/ir.h"

#include <llvm/IR/DIBuilder.h>
#include <llvm/IR/DebugLoc.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/Module.h>

#include <cstdint>
#include <map>
#include <string>

namespace mbc::codegen {

class DebugInfo {
public:
  DebugInfo(llvm::Module& module, const ir::Module& ir);

  /// The subprogram of a program's body, named after the program and
  /// starting at its first line.
  llvm::DISubprogram* subprogram(llvm::Function* fn, const ir::Function& f);

  /// The subprogram of glue code with no source of its own, put at the
  /// start of `program` (line 0 of the unit's file without one).
  llvm::DISubprogram* artificial(llvm::Function* fn,
                                 const ir::Function* program);

  llvm::DebugLoc location(std::uint32_t line, llvm::DIScope* scope);

  /// The line a program's code starts on: its first `begin`, else 1.
  static std::uint32_t firstLine(const ir::Function& f);

  /// Must come once after every function is emitted.
  void finalize();

private:
  llvm::DIFile* file(const std::string& path);
  llvm::DISubprogram* define(llvm::Function* fn, const std::string& name,
                             llvm::DIFile* f, std::uint32_t line,
                             llvm::DINode::DIFlags flags);

  llvm::DIBuilder builder_;
  llvm::DICompileUnit* unit_ = nullptr;
  llvm::DISubroutineType* type_ = nullptr;
  std::map<std::string, llvm::DIFile*> files_;
};

} // namespace mbc::codegen
