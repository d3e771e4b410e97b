// Semantic checks over parsed programs: DO/END pairing and nesting, GOTO
// targets, duplicate sequence numbers, writes to #0 and read-only system
// variables. Resolves loop partners and constant GOTO targets in place.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace mbc {

struct SemaOptions {
  /// No machine profile: the variables only a profile adds (#200-#499)
  /// cannot exist, so reading or writing one is worth a warning.
  bool defaultMachine = true;
  /// A lathe's G code system ('A', 'B', 'C'; 0 on a mill) and whether the
  /// notes a review wants are given (mbc check).
  char latheSystem = 0;
  bool reviewNotes = false;
  /// mbc check --arg: the program that runs as the main one (its index in
  /// the unit, -1 for none) and its locals the arguments set (bit n - 1
  /// for #n), which are not vacant when it starts.
  int argumentProgram = -1;
  std::uint64_t argumentLocals = 0;
};

void checkUnit(Unit& unit, DiagnosticEngine& diags,
               const SemaOptions& options = {});

/// The block a GOTO/M99 P to sequence number seq reaches from block `from`:
/// the first block with that N after `from`, searching to the end and then
/// from the top (spec Part A, "GOTO search"); -1 when there is none.
int findSequence(const Program& program, int seq, int from);

/// The blocks of each N of a program, so that the searches of a program
/// with many jumps take a binary search each rather than a scan.
class SequenceIndex {
public:
  explicit SequenceIndex(const Program& program);

  /// findSequence(program, seq, from).
  int find(int seq, int from) const;

private:
  std::unordered_map<int, std::vector<int>> blocks_; // in block order
};

/// The whole-number literal of `letter` in NC words, if any.
std::optional<int> literalWord(const std::vector<Word>& words, char letter);

} // namespace mbc
