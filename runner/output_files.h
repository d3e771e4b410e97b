// The files `mbc run` writes: toolpath JSON Lines, DPRNT text, and the
// variables JSON (replaced atomically so that a reader never sees half).
#pragma once

#include <mbc/runtime.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace mbc::runner {

/// An output stream that is a file, standard output, or nothing.
class OutputFile {
public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  /// Opens path for writing ("-" is standard output); false on failure.
  bool open(const std::string& path);

  /// Writes into memory; finish() leaves the bytes for takeMemory().
  bool openMemory();
  std::string takeMemory();

  void useStdout();

  /// Flushes (and closes a file it opened); false when anything written
  /// since open was lost (a full disk), with errno telling why.
  bool finish();

  /// Hands what was written so far to the file; false when that failed.
  bool flush();

  const std::string& path() const { return path_; }

  /// Whether every record goes out at once (standard output, a terminal).
  bool direct() const { return direct_; }

  /// The stream, for a writer of its own: flush() before handing it on
  /// when write() or writeText() wrote to it.
  std::FILE* get() const { return file_; }

  static void writeText(void* self, const char* data, std::size_t size);
  /// Writes one JSONL toolpath record; returns its bytes.
  std::size_t write(const mbrt_motion& motion);

private:
  // Records gather here and go out in blocks: one fwrite per record
  // cost as much as formatting it.
  static constexpr std::size_t kBufferBytes = 64 * 1024;

  void flushBuffer();
  void flushWhenFull();

  std::FILE* file_ = nullptr;
  // Standard output (which other outputs may share, in order) and
  // terminals get every record at once, through stdio's own buffer.
  bool direct_ = false;
  std::string buffer_;
  bool owned_ = false;
  std::string path_;
  char* memory_ = nullptr; // open_memstream's buffer
  std::size_t memorySize_ = 0;
};

/// Writes `content` to `path` so that a reader never sees half of it: a
/// regular file is replaced by rename; "-" is standard output.
bool replaceFile(const std::string& path, const std::string& content);

/// Every common variable that is not vacant, by number.
std::vector<std::pair<int, double>> commonVariables(const mbrt_ctx* ctx);
/// The same as a JSON object and a line.
std::string variablesJson(const mbrt_ctx* ctx);

/// Writes variablesJson to `path` by replaceFile.
bool writeVariables(const mbrt_ctx* ctx, const std::string& path);

} // namespace mbc::runner
