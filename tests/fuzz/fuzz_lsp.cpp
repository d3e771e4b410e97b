// libFuzzer target: any bytes as what an editor sends `mbc lsp`. The
// message reader frames them (whatever the headers say), and a document
// takes edits at positions the bytes give, in UTF-16 and UTF-8: neither
// may crash, hang or leave an offset outside the text.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "lsp/message_stream.h"
#include "lsp/text_document.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  mbc::lsp::TextSource source(bytes);
  mbc::lsp::MessageReader reader(source);
  for (int i = 0; i < 1000; ++i) {
    if (reader.next().kind == mbc::lsp::Incoming::Kind::End) {
      break;
    }
  }
  // The first half is a document, the second its edits: six bytes each
  // (start line and character, end line and character, the encoding, the
  // length of the text inserted, taken from what follows).
  const std::string_view text = bytes.substr(0, size / 2);
  std::string_view edits = bytes.substr(size / 2);
  mbc::lsp::TextDocument doc("file:///fuzz.nc", 1, std::string(text));
  while (edits.size() >= 6) {
    const auto at = [&](std::size_t i) {
      return static_cast<int>(static_cast<unsigned char>(edits[i]));
    };
    const auto encoding =
        at(4) & 1 ? mbc::lsp::Encoding::Utf8 : mbc::lsp::Encoding::Utf16;
    const mbc::lsp::Range range{{at(0) % 40, at(1)}, {at(2) % 40, at(3)}};
    const std::size_t length = std::min<std::size_t>(
        static_cast<std::size_t>(at(5) % 8), edits.size() - 6);
    doc.apply(range, edits.substr(6, length), encoding);
    edits.remove_prefix(6 + length);
    const std::size_t offset = doc.offsetOf(range.start, encoding);
    if (offset > doc.text().size() ||
        doc.offsetOf(doc.positionOf(offset, encoding), encoding) > offset) {
      std::abort();
    }
  }
  return 0;
}
