#include "toolchain/code_key.h"

#include <fmt/format.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <link.h>
#include <string_view>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <xxhash.h>

#include "toolchain/own_libraries.h"

namespace mbc::toolchain {

namespace {

class Hasher {
public:
  Hasher() { XXH3_128bits_reset(state_); }

  ~Hasher() { XXH3_freeState(state_); }

  Hasher(const Hasher&) = delete;
  Hasher& operator=(const Hasher&) = delete;

  // Length first, so that no two sequences of fields hash the same bytes.
  void add(std::string_view bytes) {
    addRaw(bytes.size());
    XXH3_128bits_update(state_, bytes.data(), bytes.size());
  }

  template <typename T> void addRaw(const T& value) {
    XXH3_128bits_update(state_, &value, sizeof value);
  }

  std::string hex() const {
    const XXH128_hash_t h = XXH3_128bits_digest(state_);
    return fmt::format("{:016x}{:016x}", h.high64, h.low64);
  }

private:
  XXH3_state_t* state_ = XXH3_createState();
};

// The main program's GNU build ID note: a hash of its code that the
// linker wrote.
int findBuildId(dl_phdr_info* info, size_t, void* data) {
  auto* out = static_cast<std::string*>(data);
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& ph = info->dlpi_phdr[i];
    if (ph.p_type != PT_NOTE) {
      continue;
    }
    const auto* p = reinterpret_cast<const char*>(info->dlpi_addr + ph.p_vaddr);
    const char* end = p + ph.p_memsz;
    while (p + sizeof(ElfW(Nhdr)) <= end) {
      ElfW(Nhdr) note;
      std::memcpy(&note, p, sizeof note);
      const char* name = p + sizeof note;
      const char* desc = name + ((note.n_namesz + 3) & ~3U);
      if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 &&
          std::memcmp(name, "GNU", 4) == 0 && desc + note.n_descsz <= end) {
        out->assign(desc, note.n_descsz);
        return 1;
      }
      p = desc + ((note.n_descsz + 3) & ~3U);
    }
  }
  return 1; // the first object is the main program: no need to look further
}

void addFileIdentity(Hasher& h, const std::string& path) {
  struct stat st {};

  if (stat(path.c_str(), &st) == 0) {
    h.addRaw(st.st_ino);
    h.addRaw(st.st_size);
    h.addRaw(st.st_mtim.tv_sec);
    h.addRaw(st.st_mtim.tv_nsec);
  }
}

void addBuild(Hasher& h) {
  std::string buildId;
  dl_iterate_phdr(findBuildId, &buildId);
  h.add(buildId);
  if (buildId.empty()) {
    addFileIdentity(h, "/proc/self/exe");
  }
  addFileIdentity(h, ownLibraries().codegen);
}

// What LLVM's host detection reads, as the kernel shows it for the first
// processor: the model and the instruction set extensions (x86, Arm,
// RISC-V keys).
void addCpu(Hasher& h) {
  utsname u{};
  if (uname(&u) == 0) {
    h.add(u.machine);
  }
  static constexpr std::array<std::string_view, 13> kKeys = {
      "vendor_id",   "cpu family",
      "model",       "model name",
      "stepping",    "flags",
      "Features",    "CPU implementer",
      "CPU variant", "CPU architecture",
      "CPU part",    "isa",
      "uarch"};
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line) && !line.empty()) {
    const std::string_view l = line;
    const auto colon = l.find(':');
    if (colon == std::string_view::npos) {
      continue;
    }
    std::string_view key = l.substr(0, colon);
    while (!key.empty() && (key.back() == ' ' || key.back() == '\t')) {
      key.remove_suffix(1);
    }
    for (std::string_view k : kKeys) {
      if (key == k) {
        h.add(l);
      }
    }
  }
}

} // namespace

std::string codeKey(const Request& r, const SourceManager& sources) {
  Hasher h;
  h.add("mbc compiled code 1");
  addBuild(h);
  addCpu(h);
  h.addRaw(r.code.optLevel);
  h.addRaw(r.code.sizeLevel);
  h.addRaw(r.code.debugInfo);
  if (r.code.debugInfo) {
    std::error_code ec;
    h.add(std::filesystem::current_path(ec).string());
  }
  h.addRaw(!r.passes.run);
  h.addRaw(r.passes.disabled.size());
  for (const std::string& pass : r.passes.disabled) {
    h.add(pass);
  }
  h.addRaw(r.trace);
  h.addRaw(r.load.errors);
  h.addRaw(sources.fileCount());
  for (std::uint32_t f = 0; f < sources.fileCount(); ++f) {
    h.add(sources.name(f));
    h.add(sources.text(f));
  }
  return h.hex();
}

} // namespace mbc::toolchain
