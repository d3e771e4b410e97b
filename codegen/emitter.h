// Internals of IR -> LLVM IR emission (emit_module.h is the interface):
// the module-wide state every function emitter shares, and the emitter of
// one function. emit_control.cpp holds blocks, phis, terminators and
// returns; emit_transfers.cpp GOTO and M99 P by sequence number;
// emit_values.cpp arithmetic and comparisons; emit_effects.cpp variables, NC
// blocks, calls and output.
#pragma once

#include "codegen/abi.h"
#include "codegen/debug_info.h"
#include "codegen/emit_module.h"
#include "ir/cfg.h"
#include "ir/ir.h"
#include <mbc/arith.h>
#include <mbc/engine.h>

#include <llvm/IR/IRBuilder.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mbc::codegen::detail {

/// What mbc.resume answers besides 0 (go on), MBRT_STOP and alarms.
inline constexpr int kResumeSeq = -2;   // M99 P from a subprogram: flow.seq
inline constexpr int kResumeLeave = -3; // M99: the program returns (leave set)

/// The key of the block-limit check among alarm ids (emit_alarms.cpp).
inline constexpr int kBlockLimit = -1;

/// IR instructions in a program beyond which its body is not optimised.
inline constexpr std::size_t kOptimizedSizeLimit = 3000;

/// A value that many blocks hand to one: a phi, or in a body too large to
/// optimise a stack slot. LLVM's instruction selection looks each phi input
/// up by a linear search of the phi's inputs, so a phi fed by every NC block
/// of a long part program makes code generation quadratic.
class Handover {
public:
  /// The receiving end, with `b` at the start of the receiving block.
  Handover(llvm::IRBuilder<>& b, llvm::BasicBlock* entry, llvm::Type* type,
           const char* name, bool inMemory);

  /// The value where it is received.
  llvm::Value* value() const { return value_; }

  llvm::BasicBlock* block() const { return block_; }

  bool used() const { return used_; }

  /// Hands `v` over from b's insert point, before it branches to block().
  void add(llvm::IRBuilder<>& b, llvm::Value* v);

private:
  llvm::BasicBlock* block_;
  llvm::Value* value_;
  llvm::AllocaInst* slot_ = nullptr;
  bool used_ = false;
};

/// The mbrt_word_kind of a word of the IR.
inline std::uint8_t runtimeWordKind(ir::WordKind kind) {
  return kind == ir::WordKind::Int   ? MBRT_WORD_INT_LITERAL
         : kind == ir::WordKind::Dec ? MBRT_WORD_DEC_LITERAL
                                     : MBRT_WORD_VALUE;
}

/// #n is a load or store in the context: a local or a fixed common.
bool isDirectVariable(std::int64_t n);
/// The builtin is computed inline: it calls nothing and writes nothing.
bool isInlineBuiltin(Builtin f);

/// What every function emitter of a module shares.
struct ModuleState {
  const ir::Module& ir;
  Abi abi;
  const EmitOptions& options;
  std::vector<llvm::Function*> bodies; // by IR function index
  llvm::Function* dispatch = nullptr;  // mbc.call, see emit_module.cpp
  llvm::Function* resume = nullptr;    // mbc.resume, see emit_module.cpp
  std::map<std::string, llvm::Constant*> strings;
  std::map<llvm::Constant*, llvm::Constant*> wordLists; // by initializer
  std::unique_ptr<DebugInfo> debug; // with EmitOptions::debugInfo only

  ModuleState(const ir::Module& m, llvm::Module& out, const EmitOptions& o)
      : ir(m), abi(out), options(o) {}

  /// A private, read-only global holding `init`.
  llvm::GlobalVariable* constantData(llvm::Constant* init, const char* name);
  /// A NUL-terminated constant string (one global per distinct text).
  llvm::Constant* cstring(const std::string& text);
  /// A constant array of mbrt_word (one global per distinct list).
  llvm::Constant* constantWords(const std::vector<llvm::Constant*>& words);
};

class FunctionEmitter {
public:
  FunctionEmitter(ModuleState& m, const ir::Function& fn, llvm::Function* body);

  void emit();

private:
  /// An LLVM edge into an IR block from an IR predecessor.
  struct Edge {
    llvm::BasicBlock* from;
    ir::BlockId pred;
  };

  // Control (emit_control.cpp).
  /// Attributes what is emitted next to `line` of the program's file.
  void at(std::uint32_t line);
  /// The line an IR instruction stands for.
  std::uint32_t lineOf(const ir::Inst& inst) const;
  void emitPrologue();
  void findStaleFile(const ir::Cfg& cfg);
  void emitBlock(ir::BlockId b);
  void fillPhis();
  /// The input `phi` takes from IR block `pred` (nullptr: none).
  llvm::Value* inputFrom(const ir::Inst& phi, ir::BlockId pred) const;

  // Runs of constant NC blocks (emit_runs.cpp).
  bool isStep(ir::BlockId b) const;
  void findRuns(const ir::Cfg& cfg);
  void emitRun(const std::vector<ir::BlockId>& run);

  // Transfers by sequence number (emit_transfers.cpp).
  void emitResume(const ir::Inst& inst);
  void storeFlow(llvm::Value* flow);
  llvm::BasicBlock* seqBlock(const ir::Inst& inst);
  llvm::BasicBlock* leftBlock();
  bool blockHasPhis(ir::BlockId b) const;
  void jumpToSeq(const ir::Inst& inst, llvm::Value* seq);
  void emitSwitch(const ir::Inst& inst);
  /// Switches on round(number) in 1..99999 to the cases of a switch or
  /// resume (ir::SequenceCases). Returns the block for every other number,
  /// with the insert point there.
  llvm::BasicBlock* switchOnSequence(const ir::Inst& inst, llvm::Value* number);
  void emitRet();
  void jump(ir::BlockId target);
  /// Goes on in a new block when `status` is 0, else leaves with it.
  void check(llvm::Value* status);
  void leave(llvm::Value* status);
  void leaveStopped(int endKind);
  void raise(int alarmId, const char* detail);

  // Alarm checks (emit_alarms.cpp).
  /// Emitted without a check of its own between others: no call, no store,
  /// no branch.
  bool isInlineValue(const ir::Inst& inst) const;
  /// Leaves with alarm `key` (an alarm id or kBlockLimit) when `cond` holds,
  /// at the next flushAlarms().
  void alarmIf(llvm::Value* cond, int key);
  /// One branch for the checks gathered since the last flush.
  void flushAlarms();
  llvm::BasicBlock* failBlock(int key);
  llvm::BasicBlock* anyFailBlock();
  /// The function's one block that calls `f(ctx, args...)` and leaves with
  /// its status: alarm sites share it, so that a big program does not get
  /// a block and an exit edge per check (LLVM's time grows with both).
  llvm::BasicBlock* sharedExit(Rt f, std::vector<llvm::Value*> args, int key);
  /// Branches on `cond` to a new block (returned, with the insert point in
  /// it) and goes on in another when it does not hold.
  llvm::BasicBlock* splitIf(llvm::Value* cond, bool unlikely);
  /// Branches on `cond` to `taken` and goes on in a new block (returned,
  /// with the insert point in it) when it does not hold.
  llvm::BasicBlock* branchOff(llvm::Value* cond, llvm::BasicBlock* taken,
                              bool unlikely);
  llvm::BasicBlock* newBlock(const char* name);

  // One switch over every operation (emit_inst.cpp).
  void emitInst(ir::ValueId id);
  llvm::Value* emitOp(const ir::Inst& inst);

  // Values (emit_values.cpp).
  llvm::Value* emitArith(const ir::Inst& inst, BinOp op);
  llvm::Value* emitCompare(const ir::Inst& inst, RelOp op);
  llvm::Value* emitFn(const ir::Inst& inst);
  llvm::Value* finite(llvm::Value* result);
  llvm::Value* positiveZero(llvm::Value* x);
  llvm::Value* isVacant(llvm::Value* x);
  llvm::Value* toNum(llvm::Value* x);
  /// Operand i as a number: vacant reads as 0 when its type is vnum.
  llvm::Value* numOperand(const ir::Inst& inst, std::size_t i);
  llvm::Value* roundHalfAway(llvm::Value* x);
  llvm::Value* constant(double x);
  llvm::Value* callStatusOut(Rt f, std::vector<llvm::Value*> args);

  // Effects (emit_effects.cpp).
  void emitBegin(const ir::Inst& inst);
  llvm::Value* emitLoadVar(int number);
  void emitStoreVar(const ir::Inst& inst, int number, llvm::Value* value);

  /// What #[x] does with a local (by index from 0), a common (by number)
  /// and any other variable (through the runtime).
  struct IndirectWays {
    std::function<llvm::Value*(llvm::Value*)> local;
    std::function<llvm::Value*(llvm::Value*)> common;
    std::function<llvm::Value*()> runtime;
  };

  llvm::Value* indirect(llvm::Value* x, const IndirectWays& ways);
  llvm::Value* emitLoadIndirect(llvm::Value* number);
  void emitStoreIndirect(const ir::Inst& inst, llvm::Value* number,
                         llvm::Value* value);
  llvm::Value* localSlot(llvm::Value* index);
  void clearAdp(llvm::Value* index);
  void clearAdpBits(llvm::Value* bits);
  /// Clears the ADP flags of the locals written since the last flush.
  void flushAdp();
  /// `inst` neither reads the ADP flags nor runs code that may.
  bool keepsAdpPending(const ir::Inst& inst) const;
  llvm::Value* commonSlot(llvm::Value* number);
  llvm::Value* emitNc(const ir::Inst& inst);
  llvm::Value* emitCallMacro(const ir::Inst& inst);

  /// A word list for the runtime: where it is and how many words it has.
  struct Words {
    llvm::Value* data;
    llvm::Value* count;
  };

  Words buildWords(const ir::Inst& inst);
  void emitPrint(const ir::Inst& inst);
  void emitTrace(const ir::Inst& inst);
  llvm::Value* message(ir::StringRef ref);
  llvm::Value* loadFlow();
  llvm::Value* scratch(llvm::Type* type, std::size_t count);

  ModuleState& m_;
  const Abi& abi_;
  const ir::Function& fn_;
  llvm::Function* body_;
  const bool large_; // beyond kOptimizedSizeLimit
  llvm::IRBuilder<> b_;
  llvm::DISubprogram* scope_ = nullptr; // with debug info only
  std::uint32_t firstLine_ = 0;
  std::vector<llvm::Value*> values_;      // by ValueId
  std::vector<llvm::BasicBlock*> blocks_; // by IR block: its first block

  std::vector<std::vector<Edge>> incoming_; // by IR block
  ir::BlockId current_ = 0;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::BasicBlock* exit_ = nullptr;
  std::optional<Handover> exitStatus_;
  llvm::Value* ctx_ = nullptr;
  llvm::Value* leave_ = nullptr;
  llvm::Value* level_ = nullptr;
  llvm::Value* commons_ = nullptr;
  llvm::Value* blockState_ = nullptr;
  // The fields of the block state every begin writes, addressed once.
  llvm::Value* blockFile_ = nullptr;
  llvm::Value* blockLine_ = nullptr;
  llvm::Value* blockCount_ = nullptr;
  llvm::Value* blockMax_ = nullptr;
  std::map<std::pair<Rt, int>, llvm::BasicBlock*> sharedExits_;
  llvm::Value* pendingFail_ = nullptr;   // i1: a gathered check holds
  llvm::Value* pendingKey_ = nullptr;    // i32: the key of the first that does
  std::optional<Handover> failKey_;      // in anyFailBlock()
  std::optional<Handover> resumeStatus_; // in leftBlock()
  std::map<std::int64_t, llvm::BasicBlock*> sharedSeq_; // by landing, or -1
  llvm::Value* file_ = nullptr;
  std::vector<char> fileStaleIn_; // by IR block: see findStaleFile
  static constexpr std::size_t kNoRun = ~std::size_t{0};
  std::vector<std::size_t> runOf_; // by IR block: its run, or kNoRun
  std::vector<std::vector<ir::BlockId>> runs_;
  bool fileStale_ = true;
  std::uint64_t pendingAdp_ = 0; // bit n: #(n+1) written, flag not cleared
  llvm::Value* name_ = nullptr;
  llvm::Value* flowSlot_ = nullptr;
  llvm::Value* outSlot_ = nullptr;
  llvm::Value* retSeqSlot_ = nullptr; // what retseq reads
  std::map<llvm::Type*, std::pair<llvm::AllocaInst*, std::size_t>> scratch_;
};

} // namespace mbc::codegen::detail
