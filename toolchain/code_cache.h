// The cache of compiled code that makes a second `mbc run` of an unchanged
// macro start without generating code (and without loading libLLVM): one
// shared object per key (code_key.h) in $MBC_CACHE_DIR, else
// $XDG_CACHE_HOME/mbc, else ~/.cache/mbc.
//
// Safe with any number of mbc processes and threads at once: an entry is
// written under a temporary name and renamed into place, so that a reader
// sees a whole entry or none; every entry ends with its length and the
// hash of its bytes, checked before it is loaded, so that a damaged or
// truncated one is removed and built again, never loaded. The cache keeps
// to a size ($MBC_CACHE_SIZE, 512M unless set) by removing the entries
// used longest ago.
#pragma once

#include <cstdint>
#include <string>

namespace mbc::toolchain {

class CodeCache {
public:
  /// The cache the environment names: a disabled one when it names none
  /// (no HOME either), or with `warning` set when MBC_CACHE_SIZE is not a
  /// size.
  static CodeCache fromEnvironment(std::string& warning);

  CodeCache(std::string dir, std::uint64_t sizeLimit)
      : dir_(std::move(dir)), sizeLimit_(sizeLimit) {}

  bool enabled() const { return !dir_.empty(); }

  const std::string& dir() const { return dir_; }

  /// The path of the entry for `key` when there is a whole one; marks it
  /// used. A damaged entry is removed.
  std::string find(const std::string& key) const;

  /// Adds the shared object `file` as the entry for `key` (the file is
  /// consumed) and returns the entry's path, then keeps the cache to its
  /// size. Empty with the reason in `error` when the cache cannot be
  /// written.
  std::string publish(const std::string& key, const std::string& file,
                      std::string& error) const;

private:
  std::string entryPath(const std::string& key) const;
  void keepToSize(const std::string& keep) const;

  std::string dir_;
  std::uint64_t sizeLimit_ = 0;
};

} // namespace mbc::toolchain
