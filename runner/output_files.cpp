// Output files of `mbc run` (see output_files.h).
#include "runner/output_files.h"

#include <mbc/limits.h>
#include <mbc/toolpath_json.h>

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

namespace mbc::runner {

OutputFile::~OutputFile() {
  finish();
  std::free(memory_);
}

void OutputFile::flushBuffer() {
  std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
  buffer_.clear();
}

void OutputFile::flushWhenFull() {
  if (direct_ || buffer_.size() >= kBufferBytes) {
    flushBuffer();
  }
}

bool OutputFile::flush() {
  flushBuffer();
  return std::fflush(file_) == 0;
}

bool OutputFile::finish() {
  if (file_ == nullptr) {
    return true;
  }
  flushBuffer();
  const bool flushed = std::fflush(file_) == 0 && std::ferror(file_) == 0;
  const int flushError = errno;
  const bool closed = !owned_ || std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed) {
    errno = flushError; // why the data was lost, not what closing said
  }
  return flushed && closed;
}

bool OutputFile::open(const std::string& path) {
  path_ = path;
  if (path == "-") {
    useStdout();
    return true;
  }
  file_ = std::fopen(path.c_str(), "wb");
  owned_ = file_ != nullptr;
  direct_ = owned_ && isatty(fileno(file_)) != 0;
  return owned_;
}

void OutputFile::useStdout() {
  file_ = stdout;
  path_ = "-";
  direct_ = true;
}

bool OutputFile::openMemory() {
  path_ = "(memory)";
  file_ = open_memstream(&memory_, &memorySize_);
  owned_ = file_ != nullptr;
  return owned_;
}

std::string OutputFile::takeMemory() {
  std::string bytes(memory_ != nullptr ? memory_ : "", memorySize_);
  std::free(memory_);
  memory_ = nullptr;
  memorySize_ = 0;
  return bytes;
}

void OutputFile::writeText(void* self, const char* data, std::size_t size) {
  auto* out = static_cast<OutputFile*>(self);
  out->buffer_.append(data, size);
  out->flushWhenFull();
}

std::size_t OutputFile::write(const mbrt_motion& motion) {
  const std::size_t before = buffer_.size();
  appendToolpathJson(buffer_, motion);
  const std::size_t bytes = buffer_.size() - before;
  flushWhenFull();
  return bytes;
}

bool replaceFile(const std::string& path, const std::string& content) {
  // Only a regular file (or a new one) is replaced through a temporary file
  // and rename; a pipe, a terminal, a symlink such as /dev/stdout or "-" is
  // written in place (appending, so a redirected stdout keeps its content).
  struct stat info;
  if (path == "-" ||
      (lstat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode))) {
    std::FILE* out = path == "-" ? stdout : std::fopen(path.c_str(), "ab");
    if (!out) {
      return false;
    }
    bool ok =
        std::fwrite(content.data(), 1, content.size(), out) == content.size();
    return (out == stdout ? std::fflush(out) : std::fclose(out)) == 0 && ok;
  }
  std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    return false;
  }
  bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size();
  // On disk before the rename, so that a crash leaves the old file or the
  // new one.
  ok = std::fflush(f) == 0 && fsync(fileno(f)) == 0 && ok;
  ok = (std::fclose(f) == 0) && ok;
  ok = ok && std::rename(tmp.c_str(), path.c_str()) == 0;
  if (!ok) {
    std::remove(tmp.c_str());
  }
  return ok;
}

std::vector<std::pair<int, double>> commonVariables(const mbrt_ctx* ctx) {
  // Room for every common of the largest machine: one pass.
  constexpr std::size_t kMost = (kLastNonvolatile - kFirstCommon + 1) +
                                (kLastCommon98000 - kFirstCommon98000 + 1);
  std::array<int, kMost> numbers;
  std::array<mbrt_num, kMost> values;
  const std::size_t count =
      mbrt_set_commons(ctx, numbers.data(), values.data(), kMost);
  std::vector<std::pair<int, double>> set;
  set.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    set.emplace_back(numbers[i], values[i]);
  }
  return set;
}

std::string variablesJson(const mbrt_ctx* ctx) {
  std::string json = "{";
  bool first = true;
  for (const auto& [n, v] : commonVariables(ctx)) {
    json += fmt::format("{}\"{}\":{}", first ? "" : ",", n, v);
    first = false;
  }
  json += "}\n";
  return json;
}

bool writeVariables(const mbrt_ctx* ctx, const std::string& path) {
  return replaceFile(path, variablesJson(ctx));
}

} // namespace mbc::runner
