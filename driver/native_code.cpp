#include "driver/native_code.h"

#include "driver/run_process.h"

#include <dlfcn.h>

namespace mbc::driver {

NativeCode::~NativeCode() {
  if (handle_ != nullptr) {
    dlclose(handle_);
  }
}

bool NativeCode::link(const std::string& object, const std::string& output,
                      std::string& error) {
  const int status = runProcess({"ld", "-shared", "-o", output, object});
  if (status == 0) {
    return true;
  }
  error = status < 0 ? "cannot run the linker 'ld'"
                     : "'ld -shared' failed to link the compiled code (exit " +
                           std::to_string(status) + ")";
  return false;
}

std::unique_ptr<NativeCode> NativeCode::open(const std::string& path,
                                             std::string& error) {
  std::unique_ptr<NativeCode> code(new NativeCode);
  // Local: two loaded objects each have a table of the same name.
  code->handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (code->handle_ == nullptr) {
    const char* why = dlerror();
    error = why != nullptr ? why : "cannot load " + path;
    return nullptr;
  }
  code->table_ = static_cast<const mbrt_program_table*>(
      dlsym(code->handle_, kLoadedTableName));
  if (code->table_ == nullptr) {
    error = path + " has no program table";
    return nullptr;
  }
  return code;
}

} // namespace mbc::driver
