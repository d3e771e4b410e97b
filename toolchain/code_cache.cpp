#include "toolchain/code_cache.h"

#include <mbc/read_file.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>
#include <xxhash.h>

#include "runner/run_options.h"
#include "toolchain/file_bytes.h"

namespace mbc::toolchain {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kDefaultSizeLimit = std::uint64_t{512} << 20;
constexpr char kTempPrefix[] = ".tmp-";
// A temporary file this old was left by a process that died while writing.
constexpr auto kAbandoned = std::chrono::hours(1);

// What follows the shared object's bytes in an entry (the dynamic loader
// reads only what the object's headers point at).
struct Trailer {
  char magic[8];
  std::uint64_t length;
  std::uint64_t hashHigh;
  std::uint64_t hashLow;
};

constexpr char kMagic[8] = {'m', 'b', 'c', 'c', 'o', 'd', 'e', '1'};

Trailer trailerOf(const std::string& bytes, std::size_t length) {
  const XXH128_hash_t h = XXH3_128bits(bytes.data(), length);
  Trailer t{};
  std::memcpy(t.magic, kMagic, sizeof kMagic);
  t.length = length;
  t.hashHigh = h.high64;
  t.hashLow = h.low64;
  return t;
}

bool isWhole(const std::string& bytes) {
  if (bytes.size() < sizeof(Trailer)) {
    return false;
  }
  const std::size_t length = bytes.size() - sizeof(Trailer);
  Trailer stored;
  std::memcpy(&stored, bytes.data() + length, sizeof stored);
  const Trailer expected = trailerOf(bytes, length);
  return std::memcmp(&stored, &expected, sizeof stored) == 0;
}

} // namespace

CodeCache CodeCache::fromEnvironment(std::string& warning) {
  std::uint64_t limit = kDefaultSizeLimit;
  if (const char* size = std::getenv("MBC_CACHE_SIZE"); size && *size) {
    if (!runner::parseSize(size, limit)) {
      warning = std::string("MBC_CACHE_SIZE '") + size +
                "' is not a size such as 512M or 2G; the cache keeps to 512M";
      limit = kDefaultSizeLimit;
    }
  }
  const char* dir = std::getenv("MBC_CACHE_DIR");
  if (dir != nullptr && *dir) {
    return {dir, limit};
  }
  // The XDG base directory specification ignores a relative path.
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg != nullptr && *xdg == '/') {
    return {std::string(xdg) + "/mbc", limit};
  }
  const char* home = std::getenv("HOME");
  if (home != nullptr && *home) {
    return {std::string(home) + "/.cache/mbc", limit};
  }
  return {"", limit};
}

std::string CodeCache::entryPath(const std::string& key) const {
  return dir_ + "/" + key + ".so";
}

std::string CodeCache::find(const std::string& key) const {
  const std::string path = entryPath(key);
  std::string bytes;
  if (readFile(path, bytes) != 0) {
    return "";
  }
  if (!isWhole(bytes)) {
    std::remove(path.c_str());
    return "";
  }
  // Used now: the last to be evicted.
  utimensat(AT_FDCWD, path.c_str(), nullptr, 0);
  return path;
}

std::string CodeCache::publish(const std::string& key, const std::string& file,
                               std::string& error) const {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  std::string bytes;
  if (readFile(file, bytes) != 0) {
    error = "cannot read " + file;
    return "";
  }
  const Trailer trailer = trailerOf(bytes, bytes.size());
  std::string temp = dir_ + "/" + kTempPrefix + key + "-XXXXXX";
  const int out = mkstemp(temp.data());
  if (out < 0) {
    error = "cannot write in the cache " + dir_ + ": " + std::strerror(errno);
    return "";
  }
  const bool written =
      fchmod(out, 0644) == 0 && writeAll(out, bytes.data(), bytes.size()) &&
      writeAll(out, reinterpret_cast<const char*>(&trailer), sizeof trailer);
  const bool closed = ::close(out) == 0;
  const std::string path = entryPath(key);
  if (!written || !closed || std::rename(temp.c_str(), path.c_str()) != 0) {
    error = "cannot write in the cache " + dir_ + ": " + std::strerror(errno);
    std::remove(temp.c_str());
    return "";
  }
  std::remove(file.c_str());
  keepToSize(path);
  return path;
}

void CodeCache::keepToSize(const std::string& keep) const {
  struct Entry {
    fs::file_time_type used;
    std::uintmax_t size;
    fs::path path;
  };

  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (const fs::directory_entry& e : fs::directory_iterator(dir_, ec)) {
    const std::string name = e.path().filename().string();
    const auto used = e.last_write_time(ec);
    if (ec) {
      continue; // removed by another process meanwhile
    }
    if (name.starts_with(kTempPrefix)) {
      if (now - used > kAbandoned) {
        fs::remove(e.path(), ec);
      }
      continue;
    }
    const std::uintmax_t size = e.file_size(ec);
    if (ec || !name.ends_with(".so")) {
      continue;
    }
    total += size;
    if (e.path() != keep) {
      entries.push_back({used, size, e.path()});
    }
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= sizeLimit_) {
      break;
    }
    fs::remove(e.path, ec);
    total -= e.size;
  }
}

} // namespace mbc::toolchain
