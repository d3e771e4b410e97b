// Helpers shared by the passes: creating, placing and removing instructions,
// rewriting uses, and dropping blocks (with the renumbering that needs).
// Removed instructions keep their slot in Function::insts as an unused
// `unreachable` in no block, like the parser's unused ids, so value ids never
// change.
#pragma once

#include "ir/ir.h"

#include <cstdint>
#include <initializer_list>
#include <vector>

namespace mbc::ir {

inline bool isTerminator(Op op) {
  return (opInfo(op).flags & Terminator) != 0;
}

/// Whether a read of #n can never alarm, whatever the machine profile: #0,
/// locals and the commons every machine has. System variables are left out:
/// some readers alarm (a tool offset beyond the profile's count).
bool readCannotAlarm(std::int64_t n);

/// Whether the flow of NC block `nc` may come from one of the M codes in
/// `codes`: one of its M words is not a constant, or is one of them. The
/// runtime's only flows for other M codes are NEXT and the END of the run
/// (runtime/src/nc_block.cpp, decideFlow): only M98 runs a subprogram on
/// this frame (whose M99 P may come back at a sequence number) and only M99
/// returns. Custom M-code calls (parameters 6071-6089) will need a look here.
bool ncMayGiveM(const Function& f, const Inst& nc,
                std::initializer_list<double> codes);

/// The terminator of `b` (its last instruction).
ValueId terminatorOf(const Function& f, BlockId b);

/// Creates an instruction that is in no block yet; returns its id.
ValueId newInst(Function& f, Op op, BlockId block, std::uint32_t line,
                std::vector<ValueId> ops = {});

/// Inserts instruction `id` into `b` at position `pos` (and sets its block).
void insertAt(Function& f, BlockId b, std::size_t pos, ValueId id);

/// The position of the first instruction of `b` that is not a phi.
std::size_t firstNonPhi(const Function& f, BlockId b);

/// Turns `id` into an unused slot. The caller takes it out of its block.
void clearInst(Function& f, ValueId id);

/// Takes every instruction with dead[id] out of its block and clears it.
void eraseInsts(Function& f, const std::vector<bool>& dead);

/// Follows repl (kNoValue: not replaced) from v to its final value.
ValueId resolve(const std::vector<ValueId>& repl, ValueId v);

/// Rewrites every operand through resolve(repl, .).
void replaceUses(Function& f, const std::vector<ValueId>& repl);

/// Replaces target `from` of a terminator by `to`.
void retarget(Inst& term, BlockId from, BlockId to);

/// Removes the inputs for predecessor `pred` from the phis of `b`.
void dropPhiInputs(Function& f, BlockId b, BlockId pred);

/// Rewrites a terminator into `br to`, dropping the phi inputs of the
/// targets it no longer reaches.
void replaceByBr(Function& f, BlockId b, BlockId to);

/// Puts a new block (a `br to`) on the edge from -> to and returns it; phis
/// of `to` take their input for `from` from the new block.
BlockId splitEdge(Function& f, BlockId from, BlockId to);

/// Removes the blocks b0 does not reach and renumbers the others in their
/// order (targets, phi inputs and Inst::block follow). True if any went.
bool removeUnreachableBlocks(Function& f);

/// Removes phis whose inputs are all one value (or the phi itself), and
/// groups of phis that only feed each other besides one outside value
/// (Braun et al. 2013, redundant phi SCCs), using that value instead, until
/// none is left. True if any went.
bool removeTrivialPhis(Function& f);

} // namespace mbc::ir
