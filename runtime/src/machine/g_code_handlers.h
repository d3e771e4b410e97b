// What the G codes of a block do (one handler per row of
// tables/g_codes.def), and the modal group each state reads back in.
#pragma once

#include "context.h"
#include "decoded_block.h"
#include "g_codes.h"

namespace mbc::rt {

/// The column of g_codes.def the profile reads G words in: 'M' on a mill,
/// the G code system on a lathe.
inline char gCodeColumn(const Profile& profile) {
  return profile.lathe() ? profile.gCodeSystem : 'M';
}

/// Notes a G word in `block.gCodes` before anything executes: most blocks
/// hold none, or only codes that set one modal field and so need no copy of
/// the modal state.
void noteGCode(const mbrt_ctx& ctx, const mbrt_word& word, NcBlock& block);

/// The block's G codes, before every other word of it: G20/G21 change how
/// its own coordinates read. Codes of one group overwrite each other, so
/// the last one of a block wins.
mbrt_status applyGCodes(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                        NcBlock& block);

/// The code (g_codes.def) of the state a modal field is in.
int modalCode(const mbrt_ctx& ctx, ModalField field);

/// #4001+g: the G code of modal group g (spec §6.4) as the profile's
/// series and G code system write it; 0 for a group mbc does not keep.
double modalGroupValue(const mbrt_ctx& ctx, int group);

} // namespace mbc::rt
