// How a variable number may be used on the default machine: the frontend's
// compile-time write checks use it; the runtime applies the same classes
// (with the machine profile's sizes) at run time.
#pragma once

#include <mbc/limits.h>

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

} // namespace mbc
