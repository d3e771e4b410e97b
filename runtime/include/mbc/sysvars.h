// How a variable number may be used on the default machine: the frontend's
// compile-time write checks use it; the runtime applies the same classes
// (with the machine profile's sizes) at run time.
#pragma once

#include <mbc/limits.h>

#include <optional>
#include <vector>

namespace mbc {

enum class VarAccess { Missing, ReadOnly, ReadWrite };

/// The access class of #n on the built-in default machine (spec §2, §6).
VarAccess variableAccess(int n);

/// #n exists on some machines only, as their profile says (#200-#499, the
/// D offsets #2401-#2800 of 6000#3 V15).
bool dependsOnProfile(int n);

/// A variable of the control's map that mbc does not model: what it holds
/// and why mbc has it not.
struct UnmodelledVariable {
  const char* meaning;
  const char* reason;
};

/// Whether #n is such a variable (PS0115 when a block reads or writes it).
bool unmodelledVariable(int n, UnmodelledVariable* out);

/// A row of the control's map of system variables (docs/control-tables.md
/// shows them): the numbers it covers, what they hold, whether mbc models
/// them (if not, PS0115 and `note` says why) and a program may write them,
/// whether they exist only on machines whose profile has them, why
/// they read what they do (or nullptr), and the unit of lengths (or
/// nullptr).
struct SystemVariableFacts {
  long first;
  long last;
  const char* meaning;
  bool readable;
  bool writable;
  bool byProfile;
  const char* note;
  const char* unit;
};

/// The row of #n, if the map has one.
std::optional<SystemVariableFacts> systemVariableFacts(int n);

/// Every row of the map from #1000 on, by number.
std::vector<SystemVariableFacts> systemVariableRows();

} // namespace mbc
