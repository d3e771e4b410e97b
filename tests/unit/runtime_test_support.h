// Helpers for the runtime's unit tests: a context with recording sinks and a
// tiny word parser, so that tests read like NC blocks ("G01 X10. F200").
#pragma once

#include <mbc/addresses.h>
#include <mbc/alarm.h>
#include <mbc/compiled.h>
#include <mbc/engine.h>
#include <mbc/toolpath_json.h>
#include <mbc/value.h>

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace mbc::test {

/// The status a call returns when it raises `id`.
inline mbrt_status status(AlarmId id) {
  return static_cast<mbrt_status>(id);
}

/// "G01 X10. Y-5 Z=1.2345": a letter and a number per word; no decimal
/// point gives an integer literal, '.' a decimal literal, '=' a computed
/// value (MBRT_WORD_VALUE).
inline std::vector<mbrt_word> parseWords(std::string_view text) {
  std::vector<mbrt_word> words;
  size_t pos = 0;
  while (pos < text.size()) {
    if (text[pos] == ' ') {
      ++pos;
      continue;
    }
    const size_t end = std::min(text.find(' ', pos), text.size());
    std::string_view word = text.substr(pos, end - pos);
    mbrt_word w{};
    w.letter = word[0];
    word.remove_prefix(1);
    if (w.letter == ',') { // ,C ,R ,A
      w.letter = mbc::commaWordLetter(word[0]);
      word.remove_prefix(1);
    }
    if (!word.empty() && word[0] == '=') {
      w.kind = MBRT_WORD_VALUE;
      word.remove_prefix(1);
    } else {
      w.kind = word.find('.') == std::string_view::npos ? MBRT_WORD_INT_LITERAL
                                                        : MBRT_WORD_DEC_LITERAL;
    }
    w.value = std::stod(std::string(word));
    words.push_back(w);
    pos = end;
  }
  return words;
}

/// The error mbrt_create gives for a bad profile ("" when it accepts it).
inline std::string profileError(const char* json) {
  char err[512] = "";
  mbrt_ctx* ctx = mbrt_create(json, err, sizeof err);
  if (ctx != nullptr) {
    mbrt_destroy(ctx);
    return "";
  }
  return err;
}

/// A context running "O1000" from "test.nc" whose sinks record everything.
class Machine {
public:
  explicit Machine(const char* profile = nullptr) {
    char err[256] = "";
    ctx_ = mbrt_create(profile, err, sizeof err);
    EXPECT_NE(ctx_, nullptr) << err;
    mbrt_set_motion_sink(ctx_, onMotion, this);
    mbrt_set_print_sink(ctx_, onPrint, this);
    mbrt_set_message_sink(ctx_, onMessage, this);
    mbrt_start(ctx_, "O1000");
  }

  ~Machine() { mbrt_destroy(ctx_); }

  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  mbrt_ctx* ctx() const { return ctx_; }

  /// Executes an NC block at test.nc:line; the flow is kept in flow().
  mbrt_status block(std::string_view text, int line = 1) {
    if (const mbrt_status status = mbrt_begin_block(ctx_, "test.nc", line)) {
      return status;
    }
    const std::vector<mbrt_word> words = parseWords(text);
    return mbrt_nc_block(ctx_, words.data(), words.size(), &flow_);
  }

  /// Executes a G65-style call with the given argument words.
  mbrt_status callMacro(const char* program, std::string_view args) {
    const std::vector<mbrt_word> words = parseWords(args);
    return mbrt_call_macro(ctx_, program, words.data(), words.size());
  }

  double read(double number) {
    mbrt_num value = 0;
    EXPECT_EQ(mbrt_read_var(ctx_, number, &value), 0) << "#" << number;
    return value;
  }

  mbrt_status write(double number, double value,
                    const char* comment = nullptr) {
    return mbrt_write_var(ctx_, number, value, comment);
  }

  std::string report() const {
    const size_t size = mbrt_alarm_report(ctx_, nullptr, 0);
    std::string text(size, '\0');
    mbrt_alarm_report(ctx_, text.data(), size + 1);
    return text;
  }

  const mbrt_flow& flow() const { return flow_; }

  const std::vector<mbrt_motion>& motions() const { return motions_; }

  const std::vector<std::string>& json() const { return json_; }

  const std::string& printed() const { return printed_; }

  const std::string& messages() const { return messages_; }

private:
  static void onMotion(void* user, const mbrt_motion* motion) {
    auto* self = static_cast<Machine*>(user);
    self->motions_.push_back(*motion);
    self->json_.push_back(toolpathJsonLine(*motion));
  }

  static void onPrint(void* user, const char* data, size_t size) {
    static_cast<Machine*>(user)->printed_.append(data, size);
  }

  static void onMessage(void* user, const char* data, size_t size) {
    static_cast<Machine*>(user)->messages_.append(data, size);
  }

  mbrt_ctx* ctx_ = nullptr;
  mbrt_flow flow_{};
  std::vector<mbrt_motion> motions_;
  std::vector<std::string> json_;
  std::string printed_;
  std::string messages_;
};

/// Points of the first two axes: (X, Y) on a mill, (X, Z) on a lathe.
using Points = std::vector<std::pair<double, double>>;

/// The end points of the motions from `first` on.
inline Points ends(const Machine& m, std::size_t first = 0) {
  Points out;
  for (std::size_t i = first; i < m.motions().size(); ++i) {
    out.emplace_back(m.motions()[i].end[0], m.motions()[i].end[1]);
  }
  return out;
}

/// Runs blocks at lines 1, 2, ..., each of which must pass; the end points
/// of every motion.
inline Points blocks(Machine& m, std::initializer_list<const char*> texts) {
  int line = 1;
  for (const char* text : texts) {
    EXPECT_EQ(m.block(text, line++), 0) << text << m.report();
  }
  return ends(m);
}

inline void expectPath(const Points& path, const Points& expected,
                       double tolerance = 1e-9) {
  ASSERT_EQ(path.size(), expected.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    EXPECT_NEAR(path[i].first, expected[i].first, tolerance) << i;
    EXPECT_NEAR(path[i].second, expected[i].second, tolerance) << i;
  }
}

} // namespace mbc::test
