// "Did you mean": the known word a misspelt one was most likely meant to
// be.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mbc::toolchain {

/// The candidate closest to `word` by edit distance (insertions, deletions,
/// substitutions and swaps of two neighbours, case-insensitive), if it is
/// close enough to be a typo of it: at most a third of the word's length,
/// and at least 1. "" when none is.
std::string closestMatch(std::string_view word,
                         const std::vector<std::string>& candidates);

} // namespace mbc::toolchain
