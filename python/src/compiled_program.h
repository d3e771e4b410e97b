// mbc.compile's C++ side: the input parsed, checked and compiled for the
// JIT (through the compiled-code cache) by the toolchain's PreparedProgram,
// its diagnostics as Python data.
#pragma once

#include <memory>
#include <pybind11/pybind11.h>
#include <string>
#include <vector>

#include "toolchain/prepared_program.h"

namespace mbc::python {

/// What mbc.compile asks for.
struct CompileRequest {
  std::vector<toolchain::SourceText> texts;
  std::vector<std::string> files;
  std::string main; // "" = the first program
  int opt = 2;
  bool cache = true;
  bool strict = true;
  bool defaultMachine = true; // no machine profile given
  std::vector<std::string> includeDirs;
};

class CompiledProgram {
public:
  /// Compiles the request. On failure (errors in the input, a file that
  /// cannot be read, no such main program) returns nullptr with the reason
  /// in `message`. The diagnostics (warnings too) go to `diagnostics` as
  /// dicts: severity, file, line, column, message, fixits, notes.
  static std::unique_ptr<CompiledProgram> compile(const CompileRequest& request,
                                                  pybind11::list& diagnostics,
                                                  std::string& message);

  const toolchain::PreparedProgram& prepared() const { return prepared_; }

  const std::string& mainName() const { return prepared_.mainName(); }

  /// Every program of the input: (name, number).
  pybind11::list programs() const;

private:
  toolchain::PreparedProgram prepared_;
};

} // namespace mbc::python
