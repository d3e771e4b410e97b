// copyprop: a phi whose inputs are all one value (or the phi itself) is a
// copy of that value; its uses take the value and the phi goes. So do
// groups of phis that only pass one outside value around among themselves.
// Folding and merging blocks leave such phis behind.
#include "ir/pass_manager.h"
#include "ir/passes/pass_util.h"

namespace mbc::ir {

void runCopyProp(Module& m) {
  for (Function& f : m.functions) {
    removeTrivialPhis(f);
  }
}

} // namespace mbc::ir
