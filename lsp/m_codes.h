// The M codes with a meaning of their own, as the editor says them: a
// short name for completion, and what a run does with the code for hover.
// Other M codes are passed on (and a profile may make them calls).
#pragma once

#include <optional>

namespace mbc::lsp {

struct MCodeText {
  int code;
  const char* name;   // "program stop"
  const char* effect; // what a run does
};

inline constexpr MCodeText kMCodes[] = {
    {0, "program stop", "the run goes on (mbc counts the stop)"},
    {1, "optional stop", "the run goes on (mbc counts the stop)"},
    {2, "end of program", "the run ends here"},
    {30, "end of program", "the run ends here"},
    {98, "subprogram call",
     "P names the program, L repeats it; the subprogram shares the caller's "
     "locals"},
    {99, "end of a subprogram or macro",
     "back to the caller (M99 P: to that N of the caller); in a main "
     "program, back to its start"},
    {198, "subprogram call from the external device",
     "P names the program, found in the external device's folder"},
};

/// The row of an M code with a meaning, if it has one.
inline std::optional<MCodeText> mCodeText(double code) {
  for (const MCodeText& m : kMCodes) {
    if (m.code == code) {
      return m;
    }
  }
  return std::nullopt;
}

} // namespace mbc::lsp
