// Calls by NC blocks (spec §5.6, §5.7). Inside a program called by a code,
// codes are ordinary codes again; inside a macro a G66 called, that G66 does
// not call again. G66.1 passes a block's words, G, L and P included.
#include "block_calls.h"

#include <mbc/arith.h>
#include <mbc/calling_codes.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "g_codes.h"
#include "g_word.h"

namespace mbc::rt {

std::string pointedWordText(char letter, double value) {
  return fmt::format("{}{}{}", letter, value,
                     value == std::trunc(value) ? "." : "");
}

namespace {

constexpr int kTCommon = 149;
constexpr int kSCommon = 147;
constexpr int kBCommon = 146;

/// The program parameter `firstParameter + i` with |value| == code calls,
/// or -1;
/// `modal` tells a negative parameter (a G66-like custom G code).
int findCode(const mbrt_ctx& ctx, const CodeTable& table, double code,
             bool* modal = nullptr) {
  if (code <= 0.0) {
    return -1;
  }
  for (int i = 0; i < table.size; ++i) {
    const double value = ctx.profile.parameter(table.firstParameter + i);
    if (std::fabs(value) == code) {
      if (modal != nullptr) {
        *modal = value < 0.0;
      }
      return table.firstProgram + i;
    }
  }
  return -1;
}

bool insideCodeCall(const mbrt_ctx& ctx) {
  return std::any_of(
      ctx.stack.calls.begin(), ctx.stack.calls.end(),
      [](const CallRecord& c) { return (c.kind & kCallCodeBit) != 0; });
}

bool insideModalCall(const mbrt_ctx& ctx, int id) {
  return std::any_of(ctx.stack.calls.begin(), ctx.stack.calls.end(),
                     [id](const CallRecord& c) { return c.modalId == id; });
}

/// The modal call a block of the running program makes: the latest G66 or
/// G66.1 in force that is not already running, so that with two in force
/// the moves of the later one's macro call the earlier one's (spec §5.6).
const ModalCall* activeModalCall(const mbrt_ctx& ctx) {
  for (auto it = ctx.stack.modalCalls.rbegin();
       it != ctx.stack.modalCalls.rend(); ++it) {
    if (!insideModalCall(ctx, it->id)) {
      return &*it;
    }
  }
  return nullptr;
}

/// G codes in tenths (G66.1 -> 661); -1 for a word that is no G code.
int gTenths(const mbrt_word& word) {
  if (word.letter != 'G') {
    return -1;
  }
  const double tenths = gWordTenths(word.value);
  return tenths >= 0.0 && tenths <= 99999.0 ? static_cast<int>(tenths) : -1;
}

const mbrt_word* findWord(const mbrt_word* words, size_t count, char letter) {
  const mbrt_word* found = nullptr;
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter == letter) {
      found = &words[i]; // the last one wins, as in the rest of the block
    }
  }
  return found;
}

long repeatOf(const mbrt_word* words, size_t count) {
  const mbrt_word* l = findWord(words, count, 'L');
  return l != nullptr ? static_cast<long>(roundHalfAway(l->value)) : 1;
}

/// The block's words but the calling one and L (and P for G66).
std::vector<mbrt_word> argumentsOf(const mbrt_word* words, size_t count,
                                   const mbrt_word* caller, bool dropP) {
  std::vector<mbrt_word> args;
  for (size_t i = 0; i < count; ++i) {
    const char letter = words[i].letter;
    if (&words[i] != caller && letter != 'L' && !(dropP && letter == 'P')) {
      args.push_back(words[i]);
    }
  }
  return args;
}

void askCall(mbrt_ctx& ctx, mbrt_flow* flow, int kind, int program, long repeat,
             std::vector<mbrt_word> args, int modalId = 0,
             bool everyBlock = false) {
  const std::size_t depth = ctx.stack.calls.size();
  if (ctx.stack.blockCalls.size() <= depth) {
    ctx.stack.blockCalls.resize(depth + 1);
  }
  BlockCall& call = ctx.stack.blockCalls[depth];
  call.args = std::move(args);
  call.modalId = modalId;
  call.everyBlock = everyBlock;
  *flow = mbrt_flow{};
  flow->kind = MBRT_FLOW_CALL;
  flow->call_kind = kind;
  flow->program = program;
  flow->repeat = repeat;
  flow->args = call.args.data();
  flow->arg_count = call.args.size();
}

void pushModalCall(mbrt_ctx& ctx, int program, long repeat, bool everyBlock,
                   std::vector<mbrt_word> args) {
  ModalCall& call = ctx.stack.modalCalls.emplace_back();
  call.id = ctx.stack.nextModalId++;
  call.program = program;
  call.repeat = repeat;
  call.everyBlock = everyBlock;
  call.args = std::move(args);
}

/// G66 P L args: the block only sets the modal call. G66.1 P L args also
/// calls the macro with its arguments, like G65.
mbrt_status setModalCall(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                         const mbrt_word& g, mbrt_flow* flow) {
  const mbrt_word* p = findWord(words, count, 'P');
  const char* name = gTenths(g) == 661 ? "G66.1" : "G66";
  if (p == nullptr) {
    return raise(ctx, AlarmId::ProgramNotFound,
                 fmt::format("{} without P", name));
  }
  // P is the program and L the count, as in G65: no decimal point.
  for (const char letter : {'P', 'L'}) {
    const mbrt_word* word = findWord(words, count, letter);
    if (word != nullptr && word->kind == MBRT_WORD_DEC_LITERAL) {
      return raise(ctx, AlarmId::IllegalDecimalPoint,
                   fmt::format("{} {}: {} takes a whole number", name,
                               pointedWordText(letter, numeric(word->value)),
                               letter));
    }
  }
  std::vector<mbrt_word> args = argumentsOf(words, count, &g, true);
  if (std::any_of(args.begin(), args.end(),
                  [](const mbrt_word& w) { return w.letter == 'G'; })) {
    return raise(ctx, AlarmId::GAsArgument,
                 fmt::format("another G code in the {} block", name));
  }
  const std::optional<int> program = calledProgramNumber(numeric(p->value));
  if (!program) {
    return raise(ctx, AlarmId::ProgramNotFound,
                 fmt::format("{} P{}", name, p->value));
  }
  const bool everyBlock = gTenths(g) == 661;
  if (everyBlock) {
    const int id =
        ctx.stack.nextModalId; // the call below is the modal call's own
    askCall(ctx, flow, MBRT_CALL_MODAL, *program, repeatOf(words, count), args,
            id);
  }
  pushModalCall(ctx, *program, repeatOf(words, count), everyBlock,
                std::move(args));
  return 0;
}

/// A custom G or M code's macro; a negative parameter makes a custom G code
/// modal like G66.
bool callCustomCode(mbrt_ctx& ctx, const mbrt_word* words, size_t count,
                    mbrt_flow* flow) {
  for (size_t i = 0; i < count; ++i) {
    const mbrt_word& word = words[i];
    bool modal = false;
    int program = -1;
    if (word.letter == 'G' && gTenths(word) % 10 == 0 &&
        mayBeCustomGCode(gTenths(word))) {
      program = findCode(ctx, kCustomGCodes, gTenths(word) / 10, &modal);
    } else if (word.letter == 'M' &&
               mayBeCustomMCode(roundHalfAway(word.value))) {
      program = findCode(ctx, kMacroMCodes, roundHalfAway(word.value));
    }
    if (program < 0) {
      continue;
    }
    std::vector<mbrt_word> args = argumentsOf(words, count, &word, false);
    if (modal) {
      pushModalCall(ctx, program, repeatOf(words, count), false,
                    std::move(args));
    } else {
      askCall(ctx, flow, MBRT_CALL_CODE_MACRO, program, repeatOf(words, count),
              std::move(args));
    }
    return true;
  }
  return false;
}

/// One transfer an executed block asks for.
struct Wanted {
  int kind;
  int program;
  int common = 0; // #149, #147 or #146 takes the code's value
  double value = 0.0;
  std::string what;
  char letter = 0; // the code that calls: M, T, S or B
};

void wantCodeSubprograms(const mbrt_ctx& ctx, const BlockCodes& codes,
                         std::vector<Wanted>& wanted) {
  for (int i = 0; i < codes.mCount; ++i) {
    const int program = mayBeCustomMCode(codes.m[i])
                            ? findCode(ctx, kSubprogramMCodes, codes.m[i])
                            : -1;
    if (program >= 0) {
      wanted.push_back({MBRT_CALL_CODE_SUB, program, 0,
                        static_cast<double>(codes.m[i]),
                        fmt::format("M{:02}", codes.m[i]), 'M'});
    }
  }
  const auto want = [&](const std::optional<double>& code, bool enabled,
                        char letter, int program, int common) {
    if (code && enabled) {
      wanted.push_back({MBRT_CALL_CODE_SUB, program, common, *code,
                        fmt::format("{}{}", letter, *code), letter});
    }
  };
  want(codes.t, ctx.profile.parameterBit(6001, 5), 'T', kTCodeProgram,
       kTCommon);
  want(codes.s, ctx.profile.parameterBit(6007, 5), 'S', kSCodeProgram,
       kSCommon);
  want(codes.b, ctx.profile.parameterBit(6007, 4), 'B', kBCodeProgram,
       kBCommon);
}

std::string flowText(const mbrt_flow& flow) {
  switch (flow.kind) {
    case MBRT_FLOW_CALL:
      return "M98";
    case MBRT_FLOW_RETURN:
      return "M99";
    default:
      return "the program end";
  }
}

} // namespace

mbrt_status callInsteadOfBlock(mbrt_ctx& ctx, const mbrt_word* words,
                               size_t count, mbrt_flow* flow, bool* taken) {
  *taken = false;
  for (size_t i = 0; i < count; ++i) {
    if (words[i].letter != 'G') {
      continue;
    }
    const int tenths = gTenths(words[i]);
    if (tenths == 660 || tenths == 661) {
      *taken = true;
      return setModalCall(ctx, words, count, words[i], flow);
    }
    if (tenths == 670 && !ctx.stack.modalCalls.empty()) {
      ctx.stack.modalCalls.pop_back(); // the rest of the block executes
      return 0;
    }
  }
  const ModalCall* modal = activeModalCall(ctx);
  if (modal != nullptr && modal->everyBlock) {
    askCall(ctx, flow, MBRT_CALL_MODAL, modal->program, modal->repeat,
            std::vector<mbrt_word>(words, words + count), modal->id, true);
    *taken = true;
    return 0;
  }
  *taken = ctx.profile.codeCalls && !insideCodeCall(ctx) &&
           callCustomCode(ctx, words, count, flow);
  return 0;
}

mbrt_status callAfterBlock(mbrt_ctx& ctx, const BlockCodes& codes,
                           mbrt_flow* flow) {
  std::vector<Wanted> wanted;
  if (ctx.profile.codeCalls && !insideCodeCall(ctx)) {
    wantCodeSubprograms(ctx, codes, wanted);
  }
  const ModalCall* modal = activeModalCall(ctx);
  if (codes.moved && modal != nullptr && !modal->everyBlock) {
    wanted.push_back({MBRT_CALL_MODAL, modal->program, 0, 0.0, "G66", 0});
  }
  if (wanted.empty()) {
    return 0;
  }
  if (wanted.size() > 1 || flow->kind != MBRT_FLOW_NEXT) {
    const std::string second =
        wanted.size() > 1 ? wanted[1].what : flowText(*flow);
    return raise(ctx, AlarmId::Unsupported,
                 fmt::format("two calls in one block ({} and {})",
                             wanted[0].what, second));
  }
  const Wanted& call = wanted[0];
  ctx.stack.callingCode = {call.letter, call.value};
  if (call.common != 0) {
    ctx.data.commons[call.common] = call.value;
  }
  if (call.kind == MBRT_CALL_MODAL) {
    askCall(ctx, flow, call.kind, call.program, modal->repeat, modal->args,
            modal->id);
  } else {
    askCall(ctx, flow, call.kind, call.program, 1, {});
  }
  return 0;
}

} // namespace mbc::rt
