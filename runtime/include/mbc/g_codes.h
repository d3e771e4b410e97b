// Which G codes the control has: the compiler's view of the runtime's G code
// table (a G word that is not one may be a custom G code's macro call).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mbc {

/// Whether G<tenths / 10>.<tenths % 10> is a G code of a FANUC 0i-MF.
bool isFanucGCode(int tenths);

/// "G28", "G54.1", "G7.5": the code as a program writes it.
std::string gCodeText(int tenths);

/// What the manual calls G<tenths> in a column ('M' for a mill, 'A', 'B'
/// or 'C' for a lathe's G code system), its modal group (0: one-shot, or
/// its words are data) and whether mbc executes it; nothing for a code the
/// column does not have.
struct GCodeFacts {
  const char* name;
  int group;
  bool modelled;
};

std::optional<GCodeFacts> gCodeFacts(char column, int tenths);

/// Every G code of a column, in tenths, in the order of the manual's list.
std::vector<std::pair<int, GCodeFacts>> gCodeList(char column);

/// The name of a FANUC G code that mbc does not execute yet (the run stops
/// with MBC0001 at it), or nullptr for codes it executes and codes FANUC
/// does not have.
const char* unmodelledGCode(int tenths);

/// What a mill's G10 L<l> sets ("a work offset", "a tool offset", "the
/// parameters that follow"), or nullptr for an L mbc does not execute (the
/// run stops with MBC0001 at it).
const char* dataInputKind(int l);

/// On a lathe in G code system `system` ('A', 'B', 'C'): the code (tenths)
/// system A writes the same function with (G77 of system B is 900, G90's
/// turning cycle), -1 when system A has no such code (G90/G91 of systems B
/// and C) or the T series none at all.
int latheFunction(char system, int tenths);

/// The name of a lathe's G code (system A tenths, as latheFunction gives)
/// that mbc does not execute yet, or nullptr.
const char* unmodelledLatheFunction(int aTenths);

} // namespace mbc
