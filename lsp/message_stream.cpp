// The base protocol's messages (see message_stream.h).
#include "lsp/message_stream.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <poll.h>
#include <unistd.h>

namespace mbc::lsp {

namespace {

/// A header line is short ("Content-Length: 123"); a longer one is no
/// header and is skipped.
constexpr std::size_t kMaxHeaderLine = 1024;
constexpr int kMaxHeaderLines = 32;

bool namesContentLength(std::string_view name) {
  constexpr std::string_view kName = "content-length";
  return name.size() == kName.size() &&
         std::equal(name.begin(), name.end(), kName.begin(),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) == b;
                    });
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) {
    text.remove_prefix(1);
  }
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) {
    text.remove_suffix(1);
  }
  return text;
}

} // namespace

bool MessageReader::readLine(std::string& line, bool& tooLong) {
  line.clear();
  tooLong = false;
  for (;;) {
    const int c = source_.next();
    if (c < 0) {
      return !line.empty();
    }
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') {
        line.pop_back();
      }
      return true;
    }
    if (line.size() < kMaxHeaderLine) {
      line.push_back(static_cast<char>(c));
    } else {
      tooLong = true;
    }
  }
}

Incoming MessageReader::next() {
  std::string line;
  bool tooLong = false;
  long long length = -1;
  std::string problem;
  int lines = 0;
  bool any = false;
  for (;;) {
    if (!readLine(line, tooLong)) {
      if (!any) {
        return {};
      }
      return {Incoming::Kind::Problem, "",
              "the input ended inside a message header"};
    }
    if (line.empty() && !tooLong) {
      if (any) {
        break;
      }
      continue; // blank lines between messages
    }
    any = true;
    if (++lines > kMaxHeaderLines || tooLong) {
      problem = "a message header that is too long";
      continue;
    }
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) {
      problem =
          fmt::format("a header line without ':' ('{}')", line.substr(0, 80));
      continue;
    }
    const std::string_view name =
        trimmed(std::string_view(line).substr(0, colon));
    if (!namesContentLength(name)) {
      continue; // Content-Type, or a header of a later protocol
    }
    const std::string_view value =
        trimmed(std::string_view(line).substr(colon + 1));
    long long n = -1;
    const auto [end, error] =
        std::from_chars(value.data(), value.data() + value.size(), n);
    if (error != std::errc() || end != value.data() + value.size() || n < 0) {
      problem = fmt::format("a Content-Length that is no length ('{}')",
                            value.substr(0, 40));
      continue;
    }
    length = n;
  }
  if (problem.empty() && length < 0) {
    problem = "a message header without Content-Length";
  }
  if (problem.empty() &&
      static_cast<unsigned long long>(length) > kMaxMessageBytes) {
    // Its body is skipped. After a bad header the length cannot be
    // trusted, so reading goes on with what follows it.
    for (long long i = 0; i < length && source_.next() >= 0; ++i) {
    }
    return {Incoming::Kind::Problem, "",
            fmt::format("a message of {} bytes, more than the {} the server "
                        "takes",
                        length, kMaxMessageBytes)};
  }
  if (!problem.empty()) {
    return {Incoming::Kind::Problem, "", problem};
  }
  std::string body;
  body.reserve(static_cast<std::size_t>(length));
  for (long long i = 0; i < length; ++i) {
    const int c = source_.next();
    if (c < 0) {
      return {Incoming::Kind::Problem, "",
              fmt::format("the input ended after {} of the {} bytes of a "
                          "message",
                          i, length)};
    }
    body.push_back(static_cast<char>(c));
  }
  return {Incoming::Kind::Message, std::move(body), ""};
}

int FdSource::next() {
  while (at_ == size_) {
    const ssize_t got = ::read(fd_, buffer_, sizeof buffer_);
    if (got < 0 && errno == EINTR) {
      continue;
    }
    if (got <= 0) {
      return -1;
    }
    at_ = 0;
    size_ = static_cast<std::size_t>(got);
  }
  return static_cast<unsigned char>(buffer_[at_++]);
}

bool FdSource::ready() {
  if (at_ < size_) {
    return true;
  }
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

void writeMessage(std::FILE* out, std::string_view json) {
  std::fprintf(out, "Content-Length: %zu\r\n\r\n", json.size());
  std::fwrite(json.data(), 1, json.size(), out);
  std::fflush(out);
}

} // namespace mbc::lsp
