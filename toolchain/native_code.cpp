#include "toolchain/native_code.h"

#include <mbc/read_file.h>

#include <dlfcn.h>
#include <sys/mman.h>
#include <unistd.h>

#include "toolchain/file_bytes.h"
#include "toolchain/run_process.h"

namespace mbc::toolchain {

namespace {

// A file on a filesystem mounted noexec (a hardened /tmp or home) cannot
// be mapped as code; the same bytes in an anonymous memory file can.
void* openFromMemory(const std::string& path) {
  std::string bytes;
  const int fd =
      readFile(path, bytes) == 0 ? memfd_create("mbc-code", MFD_CLOEXEC) : -1;
  if (fd < 0) {
    return nullptr;
  }
  void* handle = nullptr;
  if (writeAll(fd, bytes.data(), bytes.size())) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    handle = dlopen(self.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  ::close(fd); // the mapping stays
  return handle;
}

} // namespace

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
    code->handle_ = openFromMemory(path);
  }
  if (code->handle_ == nullptr) {
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

} // namespace mbc::toolchain
