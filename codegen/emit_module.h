// IR -> LLVM IR: one module per mbc module. Every program becomes an
// internal body with the mbrt_body_fn signature; a table of them (an
// mbrt_program_table named by EmitOptions::tableName) and one C entry point
// per numbered program (`mbrt_status mbc_O1000(mbrt_ctx*, const mbrt_word*,
// size_t)`, which runs it as the main program) are what other code links to.
#pragma once

#include "ir/ir.h"

#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>

#include <memory>
#include <string>
#include <vector>

namespace mbc::codegen {

struct EmitOptions {
  std::string moduleName = "mbc";
  std::string tableName = "mbc_programs";
  /// mbc_O<number> entry points for the numbered programs.
  bool entryPoints = true;
  /// A C `main` that hands its arguments and the table to mbc_aot_main
  /// (driver/aot_main.h): the executables of `mbc build`.
  bool aotMain = false;
  /// DWARF that maps the code to the .nc lines of its IR (`-g`).
  bool debugInfo = false;
  /// One part of a module compiled in parts (object_file.cpp): when not
  /// empty, only the programs whose flag is set get their body here, the
  /// others are declared. Bodies are then hidden symbols named after the
  /// table, so that the parts link to each other and to nothing else.
  std::vector<char> bodiesHere;
  /// The part with the table, the entry points and main.
  bool home = true;
};

std::unique_ptr<llvm::Module> emitModule(const ir::Module& module,
                                         llvm::LLVMContext& context,
                                         const EmitOptions& options);

/// A program is compiled as at -O0 (see emit_module.cpp): its code
/// generator level must be None (optimize.h).
bool hasUnoptimizedBody(const ir::Module& module);

/// Whether a program gets a C entry point: O-numbered ones do; a program
/// known by name only is found with mbrt_find_program.
bool hasEntryPoint(const ir::Function& f);

/// The C name of a numbered program's entry point ("mbc_O1000").
std::string entryPointName(int number);

} // namespace mbc::codegen
