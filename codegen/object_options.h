// What the code generator is asked for, apart from LLVM: the driver fills
// these in without LLVM's headers (it loads the code generator only when
// code must be generated, toolchain/code_generator.h).
#pragma once

#include <string>
#include <vector>

namespace mbc::codegen {

struct EmitOptions {
  std::string moduleName = "mbc";
  std::string tableName = "mbc_programs";
  /// mbc_O<number> entry points for the numbered programs.
  bool entryPoints = true;
  /// A C `main` that hands its arguments and the table to mbc_aot_main
  /// (runner/aot_main.h): the executables of `mbc build`.
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

enum class FileKind { LlvmIr, Assembly, Object };

struct ObjectOptions {
  EmitOptions emit;
  int optLevel = 2;
  /// -Os 1, -Oz 2: the functions are marked to be optimised for size (as
  /// clang marks them), which the passes and the code generator read.
  int sizeLevel = 0;
  /// The CPU to tune and select instructions for: "" for the architecture's
  /// generic one, "native" for this machine's.
  std::string cpu;
};

} // namespace mbc::codegen
