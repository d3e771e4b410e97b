// The flattened program (`mbc run --gcode`): every NC block the run
// executes with its words evaluated, and the offsets macro statements write
// as G10 blocks, so that a control without the macro option or a
// backplotter reproduces the run's toolpath.
#pragma once

#include "context.h"

namespace mbc::rt {

/// An executed block, less the words that called a program (M98 P L, M99
/// P, the M/T/S/B code of a code call) and G67. Only with a G-code sink.
/// `words` says how a lathe's cycle blocks read their words.
enum class LatheCycleWords {
  None,       // the block's own G codes say (G04, G51, G68...)
  AsWritten,  // G70-G73: sequence numbers, counts and lengths
  Increments, // G74-G76: P and Q count increments, even from a variable
};

void flattenBlock(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                  const mbrt_flow& flow,
                  LatheCycleWords cycle = LatheCycleWords::None);

/// A run began: the flattened program is the main program, under its O
/// number (none for a main program without one).
void flattenProgramStart(mbrt_ctx& ctx);

/// A macro statement wrote a work offset (index into workOffsets).
void flattenWorkOffset(mbrt_ctx& ctx, int offset);

/// A macro statement wrote a tool offset: L10 H geometry, L11 H wear, L12
/// D geometry, L13 D wear.
void flattenToolOffset(mbrt_ctx& ctx, int l, int number, double value);

/// A macro statement wrote a lathe's offset: G10 P (n wear, 10000 + n
/// geometry) with the word of the value written (X, Y, Z, R, Q the tip).
void flattenLatheOffset(mbrt_ctx& ctx, int p, char letter, double value);

/// Cutter compensation's look-ahead was stopped by a macro statement (a
/// read of the tool position): `blocks` dwells of 0, blocks without motion
/// in the plane, stop it for a control as well.
void flattenLookAheadStop(mbrt_ctx& ctx, int blocks);

/// A parameter a program set (G10 L52): the mode, the parameter (P the
/// axis number of a per-axis one, 0 for none) and G11, so that the
/// flattened program reads what follows as the run did.
void flattenParameter(mbrt_ctx& ctx, int number, int axis, double value);

} // namespace mbc::rt
