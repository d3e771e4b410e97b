// Compiled programs: finding one in a table, running a call of one (G65 or
// M98, with L repetitions) and the body of a main program (the API's
// mbrt_run_main starts a run around it). The IR
// evaluator runs its calls through mbrt_run_call too, so every engine
// repeats, nests and returns alike.
#include <mbc/addresses.h>

#include "context.h"

const mbrt_program* mbrt_find_program(const mbrt_program_table* table,
                                      int number, const char* name) {
  if (table == nullptr) {
    return nullptr;
  }
  for (size_t i = 0; i < table->count; ++i) {
    const mbrt_program& p = table->programs[i];
    if (number >= 0
            ? p.number == number
            : name != nullptr && mbc::namesProgram(p.name, p.number, name)) {
      return &p;
    }
  }
  return nullptr;
}

void mbrt_name_programs(mbrt_ctx* ctx, const mbrt_program_table* table) {
  for (size_t i = 0; table != nullptr && i < table->count; ++i) {
    const mbrt_program& p = table->programs[i];
    if (mbc::isNamedProgramNumber(p.number)) {
      ctx->host.programNames[p.number] = p.name;
    }
  }
}

mbrt_status mbrt_run_call(mbrt_ctx* ctx, const char* program, int kind,
                          const mbrt_word* args, size_t count, long repeat,
                          double start_seq, mbrt_body_fn body, void* user,
                          mbrt_flow* out) {
  *out = mbrt_flow{};
  for (; repeat > 0; --repeat) {
    mbrt_status st = mbrt_call(ctx, program, kind, args, count);
    if (st) {
      return st;
    }
    ctx->stack.entrySequence = start_seq;
    mbrt_flow leave{};
    if ((st = body(ctx, user, &leave))) {
      return st;
    }
    mbrt_return(ctx);
    if (leave.has_seq) {
      out->has_seq = 1;
      out->seq = leave.seq;
      return 0;
    }
  }
  return 0;
}

double mbrt_entry_sequence(const mbrt_ctx* ctx) {
  return ctx->stack.entrySequence;
}

mbrt_status mbrt_run_body(mbrt_ctx* ctx, const mbrt_program* program) {
  ctx->stack.entrySequence = 0;
  mbrt_flow leave{};
  const mbrt_status st = program->body(ctx, nullptr, &leave);
  return st > 0 ? st : 0;
}
