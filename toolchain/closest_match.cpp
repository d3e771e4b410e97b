// The optimal string alignment distance (Damerau-Levenshtein without
// repeated edits of a substring). LLVM has one (StringRef::edit_distance),
// but the driver does not link LLVM: it loads the code generator only when
// code must be generated (code_generator.h).
#include "toolchain/closest_match.h"

#include <algorithm>
#include <cctype>

namespace mbc::toolchain {

namespace {

char folded(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  // Three rows of the table: two before the current one, for swaps.
  std::vector<std::size_t> older(b.size() + 1), prev(b.size() + 1),
      row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    prev[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = folded(a[i - 1]) == folded(b[j - 1]);
      row[j] =
          std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && folded(a[i - 1]) == folded(b[j - 2]) &&
          folded(a[i - 2]) == folded(b[j - 1])) {
        row[j] = std::min(row[j], older[j - 2] + 1);
      }
    }
    std::swap(older, prev);
    std::swap(prev, row);
  }
  return prev[b.size()];
}

} // namespace

std::string closestMatch(std::string_view word,
                         const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(1, word.size() / 3);
  std::string best;
  std::size_t bestDistance = limit + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < bestDistance) {
      best = c;
      bestDistance = d;
    }
  }
  return best;
}

} // namespace mbc::toolchain
