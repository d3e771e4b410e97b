// A document the editor has open: its text as the editor last sent it,
// and the positions the protocol speaks in (a line and a character within
// it, counted in UTF-16 code units unless the client takes UTF-8), which
// the analyses turn into byte offsets and back.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mbc::lsp {

enum class Encoding { Utf16, Utf8 };

struct Position {
  int line = 0;
  int character = 0;
};

struct Range {
  Position start;
  Position end;
};

class TextDocument {
public:
  TextDocument(std::string uri, int version, std::string text);

  const std::string& uri() const { return uri_; }

  int version() const { return version_; }

  const std::string& text() const { return text_; }

  /// The byte offset of a position; a line past the last is the end of the
  /// text, a character past a line's end is that end (as the protocol
  /// says), and one inside a UTF-8 sequence is that character's start.
  std::size_t offsetOf(Position p, Encoding e) const;

  Position positionOf(std::size_t offset, Encoding e) const;

  /// An edit: `range` replaced by `text`, or the whole text when no range.
  void apply(const std::optional<Range>& range, std::string_view text,
             Encoding e);

  void setVersion(int version) { version_ = version; }

private:
  void indexLines();
  std::string_view lineAt(int line) const;

  std::string uri_;
  int version_;
  std::string text_;
  std::vector<std::size_t> lineStarts_;

  /// A character of more than one byte: positions count it as fewer
  /// units than bytes. Kept in text order with the units saved before it,
  /// so that a position on a line a megabyte long takes no counting.
  struct Wide {
    std::size_t start;
    int length;                   // bytes, cut at the line's end
    std::size_t utf16SavedBefore; // bytes minus UTF-16 units, text so far
  };

  std::vector<Wide> wide_;
};

} // namespace mbc::lsp
