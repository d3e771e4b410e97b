// Documents and their positions (see text_document.h).
#include "lsp/text_document.h"

#include <algorithm>

namespace mbc::lsp {

namespace {

/// The bytes of the UTF-8 sequence a lead byte starts (1 for a byte no
/// sequence starts with: it counts alone).
int sequenceLength(unsigned char lead) {
  if (lead >= 0xF0 && lead <= 0xF4) {
    return 4;
  }
  if (lead >= 0xE0) {
    return lead <= 0xEF ? 3 : 1;
  }
  return lead >= 0xC2 && lead <= 0xDF ? 2 : 1;
}

/// UTF-16 code units of a sequence of that many bytes.
int unitsOf(int bytes) {
  return bytes == 4 ? 2 : 1;
}

} // namespace

TextDocument::TextDocument(std::string uri, int version, std::string text)
    : uri_(std::move(uri)), version_(version), text_(std::move(text)) {
  indexLines();
}

void TextDocument::indexLines() {
  lineStarts_.assign(1, 0);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    // \n, \r\n and \r all end a line.
    if (text_[i] == '\n' ||
        (text_[i] == '\r' && (i + 1 == text_.size() || text_[i + 1] != '\n'))) {
      lineStarts_.push_back(i + 1);
    }
  }
  wide_.clear();
  std::size_t saved = 0;
  for (std::size_t line = 0; line < lineStarts_.size(); ++line) {
    const std::string_view text = lineAt(static_cast<int>(line));
    for (std::size_t byte = 0; byte < text.size();) {
      const int length =
          std::min<int>(sequenceLength(static_cast<unsigned char>(text[byte])),
                        static_cast<int>(text.size() - byte));
      if (length > 1) {
        wide_.push_back({lineStarts_[line] + byte, length, saved});
        saved += static_cast<std::size_t>(length - unitsOf(length));
      }
      byte += static_cast<std::size_t>(length);
    }
  }
}

std::string_view TextDocument::lineAt(int line) const {
  const auto i = static_cast<std::size_t>(line);
  const std::size_t begin = lineStarts_[i];
  std::size_t end =
      i + 1 < lineStarts_.size() ? lineStarts_[i + 1] : text_.size();
  while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) {
    --end;
  }
  return std::string_view(text_).substr(begin, end - begin);
}

std::size_t TextDocument::offsetOf(Position p, Encoding e) const {
  if (p.line < 0) {
    return 0;
  }
  if (static_cast<std::size_t>(p.line) >= lineStarts_.size()) {
    return text_.size();
  }
  const std::string_view line = lineAt(p.line);
  std::size_t byte = 0;
  int counted = 0;
  while (byte < line.size() && counted < p.character) {
    const int length =
        std::min<int>(sequenceLength(static_cast<unsigned char>(line[byte])),
                      static_cast<int>(line.size() - byte));
    const int units = e == Encoding::Utf8 ? length : unitsOf(length);
    if (counted + units > p.character) {
      break; // inside a character: its start
    }
    counted += units;
    byte += static_cast<std::size_t>(length);
  }
  return lineStarts_[static_cast<std::size_t>(p.line)] + byte;
}

Position TextDocument::positionOf(std::size_t offset, Encoding e) const {
  offset = std::min(offset, text_.size());
  const auto after =
      std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  const auto line = static_cast<int>(after - lineStarts_.begin()) - 1;
  const std::string_view text = lineAt(line);
  const std::size_t lineStart = lineStarts_[static_cast<std::size_t>(line)];
  const std::size_t column = std::min(offset - lineStart, text.size());
  const std::size_t target = lineStart + column;
  const auto startsBefore = [](const Wide& w, std::size_t at) {
    return w.start < at;
  };
  const auto first =
      std::lower_bound(wide_.begin(), wide_.end(), lineStart, startsBefore);
  const auto last = std::lower_bound(first, wide_.end(), target, startsBefore);
  std::size_t character = column;
  if (first != last) {
    const auto savedBefore = [&](std::vector<Wide>::const_iterator it) {
      return it == wide_.end()
                 ? wide_.back().utf16SavedBefore +
                       static_cast<std::size_t>(wide_.back().length -
                                                unitsOf(wide_.back().length))
                 : it->utf16SavedBefore;
    };
    if (e == Encoding::Utf16) {
      character -= savedBefore(last) - savedBefore(first);
    }
    // An offset inside a character counts the whole character.
    const Wide& inside = *(last - 1);
    character +=
        std::max<std::size_t>(
            inside.start + static_cast<std::size_t>(inside.length), target) -
        target;
  }
  return {line, static_cast<int>(character)};
}

void TextDocument::apply(const std::optional<Range>& range,
                         std::string_view text, Encoding e) {
  if (!range) {
    text_.assign(text);
  } else {
    const std::size_t begin = offsetOf(range->start, e);
    const std::size_t end = std::max(begin, offsetOf(range->end, e));
    text_.replace(begin, end - begin, text);
  }
  indexLines();
}

} // namespace mbc::lsp
