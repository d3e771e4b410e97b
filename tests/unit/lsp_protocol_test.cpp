// The language server's framing and positions (lsp/message_stream.h,
// lsp/text_document.h), by hand: what the protocol's base layer and its
// position rules say, case by case.
#include <gtest/gtest.h>

#include <unistd.h>

#include "lsp/message_stream.h"
#include "lsp/text_document.h"

namespace mbc::lsp {
namespace {

std::vector<Incoming> readAll(std::string_view bytes) {
  TextSource source(bytes);
  MessageReader reader(source);
  std::vector<Incoming> out;
  for (Incoming next = reader.next(); next.kind != Incoming::Kind::End;
       next = reader.next()) {
    out.push_back(next);
  }
  return out;
}

TEST(LspFraming, MessagesHeadersAndProblems) {
  // CR LF or LF alone, any case, Content-Type ignored, two in a row.
  const auto two = readAll("Content-Length: 2\r\n\r\n{}"
                           "content-length:3\nContent-Type: x\n\n[1]");
  ASSERT_EQ(two.size(), 2U);
  EXPECT_EQ(two[0].body, "{}");
  EXPECT_EQ(two[1].body, "[1]");
  // A header without a length, a length that is none: problems, and the
  // next message is read.
  const auto bad = readAll("Content-Type: x\r\n\r\n"
                           "Content-Length: -4\r\n\r\n"
                           "Content-Length: 2\r\n\r\n{}");
  ASSERT_EQ(bad.size(), 3U);
  EXPECT_EQ(bad[0].kind, Incoming::Kind::Problem);
  EXPECT_NE(bad[0].problem.find("without Content-Length"), std::string::npos);
  EXPECT_EQ(bad[1].kind, Incoming::Kind::Problem);
  EXPECT_EQ(bad[2].body, "{}");
  // A body cut short by the end of the input.
  const auto cut = readAll("Content-Length: 10\r\n\r\n{}");
  ASSERT_EQ(cut.size(), 1U);
  EXPECT_NE(cut[0].problem.find("2 of the 10 bytes"), std::string::npos);
  // A message larger than the server takes is skipped whole.
  const std::string huge =
      "Content-Length: " + std::to_string(kMaxMessageBytes + 1) + "\r\n\r\n";
  const auto big = readAll(huge);
  ASSERT_EQ(big.size(), 1U);
  EXPECT_NE(big[0].problem.find("more than"), std::string::npos);
}

TEST(LspFraming, MessagesWrittenTogetherAreReadyTogether) {
  // A request and its cancel in one write: after the first is read, the
  // second is there without waiting; after it, nothing is.
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const std::string two = "Content-Length: 2\r\n\r\n{}"
                          "Content-Length: 2\r\n\r\n[]";
  ASSERT_EQ(write(fds[1], two.data(), two.size()),
            static_cast<ssize_t>(two.size()));
  FdSource source(fds[0]);
  MessageReader reader(source);
  EXPECT_EQ(reader.next().body, "{}");
  EXPECT_TRUE(source.ready());
  EXPECT_EQ(reader.next().body, "[]");
  EXPECT_FALSE(source.ready());
  ASSERT_EQ(write(fds[1], "C", 1), 1);
  EXPECT_TRUE(source.ready()); // arrived, not read yet
  close(fds[1]);
  EXPECT_EQ(reader.next().kind, Incoming::Kind::Problem);
  EXPECT_EQ(reader.next().kind, Incoming::Kind::End);
  close(fds[0]);
}

TEST(LspPositions, Utf16Utf8AndLineEnds) {
  // "(é😀)G01": é is 2 bytes and 1 UTF-16 unit, 😀 4 bytes and 2 units.
  TextDocument doc("file:///a.nc", 1,
                   "%\r\n(\xc3\xa9\xf0\x9f\x98\x80)G01\rM30\n");
  EXPECT_EQ(doc.offsetOf({1, 5}, Encoding::Utf16), 3U + 8U);
  EXPECT_EQ(doc.offsetOf({1, 8}, Encoding::Utf8), 3U + 8U);
  EXPECT_EQ(doc.positionOf(11, Encoding::Utf16).character, 5);
  // Inside the surrogate pair: the character's start.
  EXPECT_EQ(doc.offsetOf({1, 3}, Encoding::Utf16), 3U + 3U);
  // \r alone ends line 1; past a line's end is its end; past the last line
  // the end of the text.
  EXPECT_EQ(doc.offsetOf({2, 0}, Encoding::Utf16), 15U);
  EXPECT_EQ(doc.offsetOf({0, 99}, Encoding::Utf16), 1U);
  EXPECT_EQ(doc.offsetOf({40, 0}, Encoding::Utf16), doc.text().size());
  // An incremental edit, then the whole text.
  doc.apply(Range{{2, 0}, {2, 3}}, "M02", Encoding::Utf16);
  EXPECT_EQ(doc.text().substr(15, 3), "M02");
  doc.apply(std::nullopt, "%\nO1\n%\n", Encoding::Utf8);
  EXPECT_EQ(doc.positionOf(3, Encoding::Utf8).line, 1);
}

TEST(LspPositions, OffsetsInsideCharactersAndOnEveryLine) {
  // "é" then "😀" on line 0, "€" (3 bytes, 1 unit) on line 1: every
  // offset's position, counted by hand. An offset inside a character
  // counts the whole character.
  const std::string text = "\xc3\xa9G\xf0\x9f\x98\x80X\n\xe2\x82\xac"
                           "1";
  TextDocument doc("file:///a.nc", 1, text);
  const int utf16[] = {0, 1, 1, 2, 4, 4, 4, 4, 5};
  const int utf8[] = {0, 2, 2, 3, 7, 7, 7, 7, 8};
  for (std::size_t offset = 0; offset < std::size(utf16); ++offset) {
    EXPECT_EQ(doc.positionOf(offset, Encoding::Utf16).character, utf16[offset])
        << offset;
    EXPECT_EQ(doc.positionOf(offset, Encoding::Utf8).character, utf8[offset])
        << offset;
  }
  EXPECT_EQ(doc.positionOf(9, Encoding::Utf16).line, 1);
  EXPECT_EQ(doc.positionOf(9, Encoding::Utf16).character, 0);
  EXPECT_EQ(doc.positionOf(10, Encoding::Utf16).character, 1); // inside €
  EXPECT_EQ(doc.positionOf(12, Encoding::Utf16).character, 1);
  EXPECT_EQ(doc.positionOf(13, Encoding::Utf16).character, 2);
  EXPECT_EQ(doc.positionOf(13, Encoding::Utf8).character, 4);
}

TEST(LspPositions, ALineOfAMegabyteIsNoSlower) {
  // 500 000 tokens on one line, each position asked for in turn: a count
  // from the line's start each time would take minutes.
  std::string line = "\xc3\xa9";
  for (int i = 0; i < 250000; ++i) {
    line += "+1";
  }
  TextDocument doc("file:///a.nc", 1, line + "\n");
  int last = 0;
  for (std::size_t offset = 2; offset < line.size(); offset += 2) {
    last = doc.positionOf(offset, Encoding::Utf16).character;
  }
  EXPECT_EQ(last, static_cast<int>(line.size()) - 2 - 1);
}

} // namespace
} // namespace mbc::lsp
