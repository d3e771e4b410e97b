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

/// Whether a read of #n can never alarm, whatever the machine profile: #0,
/// locals and the commons every machine has. System variables are left out:
/// some readers alarm (a tool offset beyond the profile's count).
bool readCannotAlarm(std::int64_t n);

/// Whether NC block `nc` may run code on this frame: M98 or an M code
/// subprogram (parameters 6071-6079), a T, S or B code subprogram, or M99,
/// which returns to a caller that shares it. Every such block has an M, T,
/// S or B word; the calls of other blocks (G66, custom G codes) are macros
/// with a frame of their own.
bool ncMayShareFrame(const Function& f, const Inst& nc);

/// Whether NC block `nc` may call a program by one of its own words: an M,
/// T, S or B word, or a G word that may be a custom G code (not a constant
/// G code of FANUC's; the runtime refuses profiles that give one a macro).
bool ncMayCall(const Function& f, const Inst& nc);

/// Whether any NC block of `m` may make every later block call: a G66,
/// G66.1 or modal custom G code, i.e. a G word that is not a constant G
/// code of FANUC's other than G66 and G66.1.
bool moduleMayCallByG(const Module& m);

/// The variable an ldvar or stvar names; -1 for any other instruction.
std::int64_t varNumberOf(const Inst& inst);

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
