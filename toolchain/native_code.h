// Compiled programs loaded into the process: the code generator's object
// linked into a shared object by the system linker (`ld -shared`), opened
// with dlopen. The code calls the runtime of the process that loads it:
// the mbc command exports the runtime functions of
// codegen/runtime_functions.def (driver/CMakeLists.txt).
#pragma once

#include <mbc/runtime.h>

#include <memory>
#include <string>

namespace mbc::toolchain {

/// The program table of loaded code takes this name.
inline constexpr char kLoadedTableName[] = "mbc_programs";

class NativeCode {
public:
  ~NativeCode();
  NativeCode(const NativeCode&) = delete;
  NativeCode& operator=(const NativeCode&) = delete;

  /// Links the object file `object` into the shared object `output`. False
  /// with the reason in `error`.
  static bool link(const std::string& object, const std::string& output,
                   std::string& error);

  /// Loads the shared object `path`, from a copy in memory when its
  /// filesystem forbids mapping code. Nullptr with the reason in `error`.
  static std::unique_ptr<NativeCode> open(const std::string& path,
                                          std::string& error);

  /// The compiled programs, valid while this object lives.
  const mbrt_program_table* programs() const { return table_; }

private:
  NativeCode() = default;

  void* handle_ = nullptr;
  const mbrt_program_table* table_ = nullptr;
};

} // namespace mbc::toolchain
