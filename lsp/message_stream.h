// The base protocol of the Language Server Protocol: each message is a
// header ("Content-Length: n", lines ended by CR LF, an empty line) and n
// bytes of JSON. The reader never trusts its input: a header line, a
// header or a body too long, a missing or bad length, or the end of the
// input in the middle of a message gives a problem to report, and reading
// goes on at the next message.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace mbc::lsp {

/// Where the reader takes bytes from: next() gives a byte (0-255), or -1
/// at the end.
class ByteSource {
public:
  virtual ~ByteSource() = default;
  virtual int next() = 0;
};

/// A file descriptor (the server's standard input), read in blocks of
/// its own so that it can tell what has arrived without waiting.
class FdSource final : public ByteSource {
public:
  explicit FdSource(int fd) : fd_(fd) {}

  int next() override;

  /// Whether a byte can be taken without waiting: read already, or there
  /// to read.
  bool ready();

private:
  int fd_;
  char buffer_[65536];
  std::size_t at_ = 0, size_ = 0;
};

/// Bytes in memory (the tests and the fuzzer).
class TextSource final : public ByteSource {
public:
  explicit TextSource(std::string_view text) : text_(text) {}

  int next() override {
    return at_ < text_.size() ? static_cast<unsigned char>(text_[at_++]) : -1;
  }

private:
  std::string_view text_;
  std::size_t at_ = 0;
};

/// The largest message the server takes (a 100 000-line program is about
/// 3 MB of JSON).
inline constexpr std::size_t kMaxMessageBytes = 64u << 20;

struct Incoming {
  enum class Kind { Message, Problem, End } kind = Kind::End;
  std::string body;    // Message: the JSON text
  std::string problem; // Problem: what was wrong, to log
};

class MessageReader {
public:
  explicit MessageReader(ByteSource& source) : source_(source) {}

  /// The next message, a problem with the input (then call again), or the
  /// end of the input.
  Incoming next();

private:
  /// A header line without its line end; false at the end of the input.
  bool readLine(std::string& line, bool& tooLong);

  ByteSource& source_;
};

/// Writes one message with its header and flushes it.
void writeMessage(std::FILE* out, std::string_view json);

} // namespace mbc::lsp
