// A lathe's cycles with a shape program (group 00): G70 finishing, G71
// stock removal in turning, G72 in facing, G73 pattern repeating (system A
// and B; C: G72-G75). The second block of G71-G73 (P ns, Q nf) reads the
// blocks ns to nf as they run after it: they move nothing (their moves
// are the shape), and after nf the tool roughs the stock and returns to the
// start point. G70 P Q finishes along a shape read before, or reads the one
// that follows it. In the Series 10/11 tape format (parameter 0001#1 FCV)
// G71-G73 are one block: P Q U W with D (G71/G72: the depth; G73: the
// divisions) and G73's I K, the rest from parameters. mbc reads a shape as
// it runs, so block ns must be the first NC block after the cycle's; a
// program that jumps back to it stops with MBC0001.
#pragma once

#include <optional>

#include "frame_words.h"
#include "lathe_state.h"

namespace mbc::rt {

/// A G70-G73 block (`code` as lathe_codes.h numbers them): the first block
/// keeps its settings, the second starts reading its shape (or G70
/// finishes along one read before).
mbrt_status startShapeCycle(mbrt_ctx& ctx, int code, const FrameWords& words);

/// The axis words of an NC block of the shape (bit a: axis a written):
/// block ns that writes the cut axis too (Z for G71, X for G72; W0
/// counts) makes the cycle type II, as the control decides.
void readShapeWords(mbrt_ctx& ctx, std::uint32_t axisMask);

/// Around each NC block while a shape is read: `n` is the block's sequence
/// number. The first must be ns; a block that calls or ends is PS0066;
/// after nf the cycle runs.
mbrt_status enterShapeBlock(mbrt_ctx& ctx, std::optional<double> n);
mbrt_status leaveShapeBlock(mbrt_ctx& ctx, std::optional<double> n,
                            const mbrt_flow& flow, mbrt_status status);

} // namespace mbc::rt
