// The last value of each address the control remembers, #4101 + index
// (#4102 B ... #4130 the P of G54.1): one table for the block reader that
// keeps them, the moves that read them and the system variables.
#pragma once

#include <cstddef>

namespace mbc::rt {

/// The index into MachineState::lastWords: #4101 + index.
enum class LastWord : int {
  B = 1,        // #4102
  D = 6,        // #4107
  E = 7,        // #4108
  F = 8,        // #4109
  H = 10,       // #4111
  M = 12,       // #4113
  N = 13,       // #4114
  Program = 14, // #4115: the program number, read from the call stack
  S = 18,       // #4119
  T = 19,       // #4120
  G541P = 29,   // #4130: the P of G54.1
};

inline constexpr std::size_t kLastWordCount = 30; // #4101..#4130

constexpr std::size_t lastWordSlot(LastWord word) {
  return static_cast<std::size_t>(word);
}

/// The last word an address letter of an NC block sets, -1 for one the
/// control does not remember.
constexpr int lastWordIndex(char letter) {
  constexpr struct {
    char letter;
    LastWord word;
  } kLetters[] = {{'B', LastWord::B}, {'D', LastWord::D}, {'E', LastWord::E},
                  {'F', LastWord::F}, {'H', LastWord::H}, {'M', LastWord::M},
                  {'N', LastWord::N}, {'S', LastWord::S}, {'T', LastWord::T}};

  for (const auto& entry : kLetters) {
    if (entry.letter == letter) {
      return static_cast<int>(entry.word);
    }
  }
  return -1;
}

} // namespace mbc::rt
