// Calls: macro calls with their argument mapping (specification I and II,
// spec §5.2-5.4; a G66.1 block's words), subprogram calls, returns and the
// nesting limits (PS0122, PS0077).
#include "calls.h"

#include <mbc/addresses.h>

#include <fmt/format.h>

#include <vector>

#include "context.h"

namespace mbc::rt {

namespace {

bool scalesLiteral(const mbrt_ctx& ctx, char letter) {
  return ctx.movedAxisOf(letter) >= 0 || letter == 'I' || letter == 'J' ||
         letter == 'K' || letter == 'R' || letter == 'Q';
}

/// A G66.1 block passes its G, L and P too: to the locals their letters
/// leave free in specification I.
int everyBlockLocal(char letter) {
  switch (letter) {
    case 'G':
      return 10;
    case 'L':
      return 12;
    case 'P':
      return 16;
    default:
      return 0;
  }
}

/// Which local an argument sets, or the alarm for a letter that is no
/// argument.
mbrt_status argumentLocal(mbrt_ctx& ctx, char letter, bool everyBlock,
                          IjkSets& sets, int* local) {
  if (everyBlock && everyBlockLocal(letter) != 0) {
    *local = everyBlockLocal(letter);
    return 0;
  }
  if (letter == 'G') {
    return raise(ctx, AlarmId::GAsArgument);
  }
  if (letter == 'I' || letter == 'J' || letter == 'K') {
    *local = sets.next(letter - 'I');
    if (*local == 0) {
      return raise(
          ctx, AlarmId::MacroStatementFormat,
          fmt::format("more than {} I, J, K argument sets", kMaxIjkSets));
    }
    return 0;
  }
  *local = mbc::argumentLocal(letter);
  if (*local == 0) {
    return raise(
        ctx, AlarmId::MacroStatementFormat,
        fmt::format("{} cannot be a macro argument", addressText(letter)));
  }
  return 0;
}

/// Fills a fresh level from the argument words; later words win.
mbrt_status mapArguments(mbrt_ctx& ctx, const mbrt_word* args, size_t count,
                         bool everyBlock, LocalLevel& level) {
  IjkSets sets;
  for (size_t i = 0; i < count; ++i) {
    const mbrt_word& word = args[i];
    int local = 0;
    if (const mbrt_status status =
            argumentLocal(ctx, word.letter, everyBlock, sets, &local)) {
      return status;
    }
    const std::uint64_t bit = std::uint64_t{1} << (local - 1);
    // X10 passes 0.010 mm (spec §5.4); ADP gives the 10 back.
    if (word.kind == MBRT_WORD_INT_LITERAL && scalesLiteral(ctx, word.letter) &&
        !ctx.profile.decimalPointInput) {
      level.value[local - 1] =
          word.value / addressCountsPerUnit(ctx, word.letter);
      level.adp_mask |= bit;
    } else {
      level.value[local - 1] = word.value;
      level.adp_mask &= ~bit;
    }
  }
  return 0;
}

/// PS0077 when one more call would exceed the total nesting limit.
mbrt_status checkTotalNesting(mbrt_ctx& ctx) {
  if (static_cast<int>(ctx.stack.calls.size()) + 1 > ctx.profile.totalNesting) {
    return raise(
        ctx, AlarmId::TooManySubMacroNesting,
        fmt::format("more than {} nested calls", ctx.profile.totalNesting));
  }
  return 0;
}

void pushCall(mbrt_ctx& ctx, const char* program, int kind) {
  const std::size_t depth = ctx.stack.calls.size();
  CallRecord& call = ctx.stack.calls.emplace_back();
  call.program = program != nullptr ? program : "";
  call.programNumber = parseProgramNumber(program);
  call.kind = kind;
  if ((kind & kCallModalBit) != 0 && depth < ctx.stack.blockCalls.size()) {
    call.modalId = ctx.stack.blockCalls[depth].modalId;
  }
  call.file = ctx.run.block.file;
  call.line = ctx.run.block.line;
}

mbrt_status enterMacro(mbrt_ctx& ctx, const char* program, int kind,
                       const mbrt_word* args, size_t count) {
  if (ctx.stack.macroDepth + 1 > ctx.profile.macroNesting) {
    return raise(ctx, AlarmId::TooManyMacroNesting,
                 fmt::format("more than {} nested macro calls",
                             ctx.profile.macroNesting));
  }
  if (const mbrt_status status = checkTotalNesting(ctx)) {
    return status;
  }
  // A G66.1 block's words are its arguments, G, L and P included.
  const bool everyBlock =
      (kind & kCallModalBit) != 0 &&
      ctx.stack.calls.size() < ctx.stack.blockCalls.size() &&
      ctx.stack.blockCalls[ctx.stack.calls.size()].everyBlock;
  ctx.stack.levels.emplace_back();
  if (const mbrt_status status =
          mapArguments(ctx, args, count, everyBlock, ctx.stack.levels.back())) {
    ctx.stack.levels.pop_back();
    return status;
  }
  ++ctx.stack.macroDepth;
  pushCall(ctx, program, kind);
  return 0;
}

mbrt_status enterSub(mbrt_ctx& ctx, const char* program, int kind) {
  if (ctx.stack.subDepth + 1 > ctx.profile.subprogramNesting) {
    return raise(ctx, AlarmId::TooManySubMacroNesting,
                 fmt::format("more than {} nested subprogram calls",
                             ctx.profile.subprogramNesting));
  }
  if (const mbrt_status status = checkTotalNesting(ctx)) {
    return status;
  }
  ++ctx.stack.subDepth;
  pushCall(ctx, program, kind);
  return 0;
}

} // namespace

double argumentScale(const mbrt_ctx& ctx, int local) {
  for (char letter = 'A'; letter <= 'Z'; ++letter) {
    if (mbc::argumentLocal(letter) == local && scalesLiteral(ctx, letter)) {
      return addressCountsPerUnit(ctx, letter);
    }
  }
  return ctx.inputScale(); // the I, J, K of specification II
}

} // namespace mbc::rt

using namespace mbc;
using namespace mbc::rt;

mbrt_status mbrt_call(mbrt_ctx* ctx, const char* program, int kind,
                      const mbrt_word* args, size_t count) {
  if (const mbrt_status status =
          checkProgramNumber(*ctx, parseProgramNumber(program))) {
    return status;
  }
  return (kind & kCallMacroBit) != 0
             ? enterMacro(*ctx, program, kind, args, count)
             : enterSub(*ctx, program, kind);
}

mbrt_status mbrt_call_macro(mbrt_ctx* ctx, const char* program,
                            const mbrt_word* args, size_t count) {
  return mbrt_call(ctx, program, MBRT_CALL_MACRO, args, count);
}

mbrt_status mbrt_call_sub(mbrt_ctx* ctx, const char* program) {
  return mbrt_call(ctx, program, MBRT_CALL_SUB, nullptr, 0);
}

void mbrt_return(mbrt_ctx* ctx) {
  if (ctx->stack.calls.empty()) {
    return;
  }
  if ((ctx->stack.calls.back().kind & kCallMacroBit) != 0) {
    ctx->stack.levels.pop_back();
    --ctx->stack.macroDepth;
  } else {
    --ctx->stack.subDepth;
  }
  ctx->stack.calls.pop_back();
}

int mbrt_call_depth(const mbrt_ctx* ctx) {
  return static_cast<int>(ctx->stack.calls.size());
}

mbrt_status mbrt_set_main_args(mbrt_ctx* ctx, const mbrt_word* args,
                               size_t count) {
  // A host's 'x' is X, as the control reads a lower-case letter and the
  // Python package and batch tables take one (no comma word is an
  // argument).
  std::vector<mbrt_word> upper(args, args + count);
  for (mbrt_word& word : upper) {
    if (word.letter >= 'a' && word.letter <= 'z') {
      word.letter = static_cast<char>(word.letter - 'a' + 'A');
    }
  }
  LocalLevel level;
  if (const mbrt_status status =
          mapArguments(*ctx, upper.data(), count, false, level)) {
    return status;
  }
  ctx->stack.levels.front() = level;
  return 0;
}
