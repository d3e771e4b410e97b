/* The runtime's C ABI for engines: what the reference interpreter, the IR
 * evaluator and generated code (JIT and AOT) call while they run a program
 * (blocks, words, calls, DPRNT, raising alarms). Embedders use
 * mbc/runtime.h, which this header includes; mbc/compiled.h adds what only
 * generated code uses. Not installed: it changes with the engines.
 */
#ifndef MBC_ENGINE_H
#define MBC_ENGINE_H

#include <mbc/runtime.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Profile settings -------------------------------------------------
 */

/* A parameter of the machine profile (its default when the profile does not
 * set it; 0 for a number mbc does not model, docs/machine-profile.md). */
double mbrt_parameter(const mbrt_ctx* ctx, int number);

/* The G code system of a lathe's profile ('A', 'B' or 'C'; "series":
 * "T"), 0 for a machining centre. */
int mbrt_lathe_system(const mbrt_ctx* ctx);

/* 1 when the profile turns the optional block skip switch on: blocks
 * starting with '/' are skipped. */
int mbrt_block_skip(const mbrt_ctx* ctx);

/* 1 when switch /n is on (the profile's switch counts as /1). */
int mbrt_skip_switch(const mbrt_ctx* ctx, int n);

/* ---- Execution bookkeeping --------------------------------------------
 */

/* Starts a run of the named main program at call level 0, from the machine
 * state the last run left, as a control starts a program after RESET: a new
 * call stack, locals, block count, statistics and motion buffer, no alarm;
 * the position, modal codes (G90/G91, plane, G20/G21, work offset, F...)
 * and frames (G92, G52, G68...) stay, while modal calls (G66), canned cycles
 * and cutter compensation are cancelled. Profile parameter 3402#6 CLR puts
 * the modal codes back to their power-on values too. */
void mbrt_start(mbrt_ctx* ctx, const char* main_program);

/* Called by an engine at the start of every executed block: counts it,
 * enforces the execution limit and remembers the location for alarms. The
 * runtime keeps the file pointer (it is passed on in mbrt_motion), so it must
 * stay valid until the run ends. */
mbrt_status mbrt_begin_block(mbrt_ctx* ctx, const char* file, int line);

int mbrt_tracing(const mbrt_ctx* ctx);

/* Writes "file:line: text" for the current block to the trace sink. */
void mbrt_trace(mbrt_ctx* ctx, const char* text);

/* Traces a template whose holes take the values in order: "{}" a value
 * ("<vacant>" when vacant), "{#}" a variable number (rounded half away from
 * zero), "{?}" a truth ("true" unless 0). frontend/trace_text.h makes the
 * templates of the statements engines run themselves. */
void mbrt_trace_values(mbrt_ctx* ctx, const char* tmpl, const mbrt_num* values,
                       size_t count);

enum mbrt_end_kind {
  MBRT_END_PROGRAM = 0, /* end of the main program's text or '%' */
  MBRT_END_M02_M30 = 1, /* counts a part (#3901) */
  MBRT_END_MAIN_M99 = 2 /* M99 in the main program (a control would loop) */
};

/* Normal end of the run: records how it ended and flushes the sinks. */
void mbrt_finish(mbrt_ctx* ctx, int end_kind);

/* ---- Variables --------------------------------------------------------
 */

/* ADP[#number]: a local set from a macro argument written without decimal
 * point gets its decimal point back (X10 -> 0.010 -> 10.0). */
mbrt_status mbrt_adp(mbrt_ctx* ctx, double number, mbrt_num* out);

/* ---- NC blocks and calls ----------------------------------------------
 */

/* Which of PRM's optional operands are given (a mask). */
enum mbrt_parameter_form {
  MBRT_PARAMETER_BIT = 1, /* PRM[n, bit] */
  MBRT_PARAMETER_AXIS = 2 /* PRM[n]/[axis] */
};

/* PRM: the value of parameter `number` (with MBRT_PARAMETER_BIT only bit
 * `bit` of it, 0 or 1; with MBRT_PARAMETER_AXIS of axis number `axis`,
 * 1 up), for the parameters a
 * machine profile may set; MBC0001 for another, PS0119 for a bit or axis
 * the parameter does not have. */
mbrt_status mbrt_read_parameter(mbrt_ctx* ctx, int form, double number,
                                double bit, double axis, double* out);

/* The least input increment of an address (0.001 for metric axes, 1 for
 * integer addresses): ROUND written directly in an address rounds to it. */
double mbrt_address_increment(const mbrt_ctx* ctx, char letter);

enum mbrt_flow_kind {
  MBRT_FLOW_NEXT = 0,   /* go on with the next block */
  MBRT_FLOW_CALL = 1,   /* call a program (M98, G66, a custom code...) */
  MBRT_FLOW_RETURN = 2, /* M99 [P seq] */
  MBRT_FLOW_END = 3     /* M02 / M30 */
};

/* How a program is called. Bit 0: a new local level; bit 1: called by a
 * code (custom G/M code, M/T/S/B code subprogram), inside which codes no
 * longer call programs; bit 2: called by G66/G66.1, whose own modal call is
 * off inside. */
enum mbrt_call_kind {
  MBRT_CALL_SUB = 0,        /* M98 */
  MBRT_CALL_MACRO = 1,      /* G65 */
  MBRT_CALL_CODE_SUB = 2,   /* M code (6071-6079), T, S, B code */
  MBRT_CALL_CODE_MACRO = 3, /* custom G code (6050-6059), M code (6080-) */
  MBRT_CALL_MODAL = 5       /* G66 after a move, G66.1 at every block */
};

struct mbrt_flow {
  int kind;        /* mbrt_flow_kind */
  int program;     /* CALL: program number */
  long repeat;     /* CALL: repeat count (L, or M98's legacy high P digits) */
  int has_seq;     /* M99 P given */
  double seq;      /* M99 P: sequence number to resume at in the caller */
  int counts_part; /* M02/M30 */
  int call_kind;   /* CALL: mbrt_call_kind */
  /* CALL of a macro: its arguments, valid until the block's call level
   * executes its next NC block. */
  const mbrt_word* args;
  size_t arg_count;
  /* CALL by M98/M198 Q: the sequence number the program starts at; 0 from
   * its top. */
  double start_seq;
};

/* Executes an NC block (modal G codes, motion, canned cycles, F S T M H D
 * words) and tells the engine what control transfer it asks for: the
 * engine makes the calls (mbrt_run_call with flow->call_kind). */
mbrt_status mbrt_nc_block(mbrt_ctx* ctx, const mbrt_word* words, size_t count,
                          mbrt_flow* flow);

/* Traces "head" followed by the words ("X10 Y-2"). mbrt_nc_block traces its
 * own words. Engines trace a G65 call with mbrt_trace_call ("G65 P L" and
 * the arguments) before they look the program up. */
void mbrt_trace_words(mbrt_ctx* ctx, const char* head, const mbrt_word* words,
                      size_t count);

void mbrt_trace_call(mbrt_ctx* ctx, mbrt_num program, mbrt_num repeat,
                     const mbrt_word* words, size_t count);

/* Enters a call of `program` (mbrt_call_kind): a macro gets a new local
 * level whose #1..#33 are set from the argument words (specification I and
 * II, spec §5.2-5.4; a G66.1 block's G, L and P go to #10, #12, #16), a
 * subprogram shares the caller's. Checks nesting (PS0122, PS0077). */
mbrt_status mbrt_call(mbrt_ctx* ctx, const char* program, int kind,
                      const mbrt_word* args, size_t count);

/* mbrt_call of a G65 macro. */
mbrt_status mbrt_call_macro(mbrt_ctx* ctx, const char* program,
                            const mbrt_word* args, size_t count);

/* `mbc run --arg`: sets the main program's #1..#33 from argument words with
 * the G65 mapping, without a new call level. Call after mbrt_start. */
mbrt_status mbrt_set_main_args(mbrt_ctx* ctx, const mbrt_word* args,
                               size_t count);

/* mbrt_call of an M98 subprogram. */
mbrt_status mbrt_call_sub(mbrt_ctx* ctx, const char* program);

/* M99: leaves the innermost call, restoring the caller's locals for G65. */
void mbrt_return(mbrt_ctx* ctx);

/* 0 in the main program. */
int mbrt_call_depth(const mbrt_ctx* ctx);

/* ---- Running programs -------------------------------------------------
 */

/* A body returns this when the run ended (M02/M30, M99 or the end of the
 * main program's text; mbrt_finish was called). */
#define MBRT_STOP (-1)

/* A call of `body` (kind: mbrt_call_kind), `repeat` times (none when <= 0):
 * each time mbrt_call, the body, the return; an M99 P stops the repetitions
 * and is passed on in out->has_seq/seq. Each time the body starts at
 * sequence number `start_seq` (M98 Q; 0: at its top), which it reads with
 * mbrt_entry_sequence. */
mbrt_status mbrt_run_call(mbrt_ctx* ctx, const char* program, int kind,
                          const mbrt_word* args, size_t count, long repeat,
                          double start_seq, mbrt_body_fn body, void* user,
                          mbrt_flow* out);

/* The sequence number the program just entered starts at (M98 P Q, M98 Q),
 * 0 for its first block. A body reads it before anything else. */
double mbrt_entry_sequence(const mbrt_ctx* ctx);

/* Runs a program as the main program from the current state (after
 * mbrt_start and any variable presets): 0 or the alarm that stopped it. */
mbrt_status mbrt_run_body(mbrt_ctx* ctx, const mbrt_program* program);

/* ---- Output statements ------------------------------------------------
 */

/* One DPRNT/BPRNT item: text (with '*' already kept as written; the runtime
 * prints it as a space) or a value with its [c d] format. */
typedef struct mbrt_print_item {
  const char* text; /* non-NULL: literal text */
  mbrt_num value;
  int int_digits;  /* c (DPRNT only) */
  int frac_digits; /* d */
} mbrt_print_item;

mbrt_status mbrt_dprnt(mbrt_ctx* ctx, const mbrt_print_item* items,
                       size_t count);

mbrt_status mbrt_bprnt(mbrt_ctx* ctx, const mbrt_print_item* items,
                       size_t count);

mbrt_status mbrt_popen(mbrt_ctx* ctx);

mbrt_status mbrt_pclos(mbrt_ctx* ctx);

/* ---- Raising alarms ---------------------------------------------------
 */

/* Raises an alarm found by the engine (division by zero, GOTO target...).
 * detail (may be NULL) is appended to the message. Returns the id. The first
 * alarm of a run is the one kept and reported. */
mbrt_status mbrt_raise(mbrt_ctx* ctx, int alarm_id, const char* detail);

/* The alarms of control transfers, worded alike by every engine (PS0128):
 * `jump` ("GOTO " or "M99 P") names a target outside 1..99999, otherwise
 * "N<seq> not found in <program>". */
mbrt_status mbrt_raise_sequence(mbrt_ctx* ctx, const char* jump, double seq,
                                const char* program);

/* PS0078 "M98 Q<seq>" or "N<seq> not found in <program>": the sequence
 * number a call asked its program to start at is not there. */
mbrt_status mbrt_raise_start_sequence(mbrt_ctx* ctx, double seq,
                                      const char* program);

/* PS0076 "O<number>": a called program that does not exist (PS0074 when
 * the number has more digits than the machine's program numbers). */
mbrt_status mbrt_raise_program_not_found(mbrt_ctx* ctx, double number);

#ifdef __cplusplus
}
#endif

#endif /* MBC_ENGINE_H */
