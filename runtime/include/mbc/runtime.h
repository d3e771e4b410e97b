/* The C ABI of the mbc runtime: one library that every engine calls (the
 * reference interpreter, the IR evaluator, JIT and AOT code). It owns the
 * machine: variables and system variables, call frames, modal state, the
 * motion sink, DPRNT/BPRNT output and alarms. No globals: every call takes the
 * context, so contexts are independent.
 *
 * Every fallible call returns an mbrt_status: 0 to go on, otherwise the alarm
 * that stops the run. The context keeps the alarm, its message and the block
 * (file:line) it happened in; mbrt_alarm_report formats it.
 */
#ifndef MBC_RUNTIME_H
#define MBC_RUNTIME_H

#include <mbc/version.h>

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct mbrt_ctx mbrt_ctx;

/* A variable's value: an IEEE double, or vacant (a reserved NaN, see
 * mbc/value.h). */
typedef double mbrt_num;

/* MBRT_OK (0) = success; otherwise an alarm id, one of mbrt_alarm_id. */
typedef int mbrt_status;

#define MBRT_OK 0

/* The alarm ids by name, in the order of mbc/alarms.def, where each row
 * gives the control's number and message (MBRT_ALARM_ZeroDivide is PS0112
 * ZERO DIVIDE); rows are only ever added at the end, so the values stay.
 * mbrt_alarm_number and mbrt_alarm_code give the pending alarm as the
 * control shows it. */
enum mbrt_alarm_id {
  MBRT_ALARM_None,

#define ALARM(Id, Prefix, Number, Message) MBRT_ALARM_##Id,
#include <mbc/alarms.def>
};

/* The version of the runtime library linked (MBC_VERSION_STRING is the
 * header's). */
const char* mbrt_version(void);

#define MBRT_MAX_AXES 8

/* ---- Context -------------------------------------------------------------
 */

/* A context for the machine described by a profile (JSON text, see
 * docs/machine-profile.md); NULL selects the built-in 3-axis metric vertical
 * mill. On a bad profile returns NULL and writes the reason to err. */
mbrt_ctx* mbrt_create(const char* profile_json, char* err, size_t err_size);
mbrt_ctx* mbrt_create_from_file(const char* path, char* err, size_t err_size);
void mbrt_destroy(mbrt_ctx* ctx);

/* ---- Sinks ---------------------------------------------------------------
 */

enum mbrt_motion_kind {
  MBRT_MOTION_RAPID = 0,
  MBRT_MOTION_LINEAR = 1,
  MBRT_MOTION_CW = 2,
  MBRT_MOTION_CCW = 3
};

/* One executed motion, in input units (mm or inch) rounded to the least
 * input increment. `end` and `center` are in the active workpiece coordinate
 * system (G54..G59, G54.1, after G92) with the G52 local origin, mirror,
 * scaling and rotation applied and without the tool length offset;
 * `machine` is the control point in machine coordinates. */
typedef struct mbrt_motion {
  int kind;                  /* mbrt_motion_kind */
  int axis_count;            /* machine axes, in profile order */
  const char* axis_names;    /* one letter per axis, e.g. "XYZ" */
  double end[MBRT_MAX_AXES]; /* end point of every axis */
  double feed;               /* F (not for rapids) */
  int plane;                 /* 17, 18 or 19: the arc plane */
  char center_axes[2];       /* the two plane axes, e.g. 'X','Y' */
  double center[2];          /* absolute arc centre (arcs only) */
  int decimals;              /* digits of the least input increment (3, 4) */
  const char* file;          /* source of the block */
  int line;
  const char* program; /* "O1000", "<NAME>" or "MAIN" */
  int cycle;           /* the canned cycle making the move (81 for G81), 0 */
  double machine[MBRT_MAX_AXES]; /* end point in machine coordinates */
  double start[MBRT_MAX_AXES];   /* where the move began, like `end` */
  /* The block's end point as the program commands it, like `end`: under
   * cutter compensation `end` is the tool centre, beside it. */
  double programmed[MBRT_MAX_AXES];
} mbrt_motion;

/* Sinks run in the middle of a block: from inside one, mbrt_run_main (and
 * the mbc_O<n> entry points), mbrt_start, mbrt_reset_state, mbrt_reset and
 * mbrt_destroy do nothing, and the run stops before its next block with
 * alarm MBC0007. */
typedef void (*mbrt_motion_fn)(void* user, const mbrt_motion* motion);
typedef void (*mbrt_text_fn)(void* user, const char* data, size_t size);

void mbrt_set_motion_sink(mbrt_ctx* ctx, mbrt_motion_fn fn, void* user);
/* DPRNT/BPRNT bytes. */
void mbrt_set_print_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user);
/* Operator messages (#3006, M00/M01 notes), one line each with '\n'. */
void mbrt_set_message_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user);
/* --trace lines ("file:line: text\n"); fn NULL switches tracing off. */
void mbrt_set_trace_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user);
/* The flattened program (mbc run --gcode): one line per NC block executed,
 * words evaluated, without the words that called a program (M98 P L, M99
 * P, an M/T/S/B code that called a subprogram), and G10 lines for the
 * offsets macro statements write. */
void mbrt_set_gcode_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user);
/* Alarms as they are raised: fn gets the text mbrt_alarm_report gives. The
 * call that raised it then returns the alarm id, which unwinds to the
 * caller of the program. */
void mbrt_set_alarm_sink(mbrt_ctx* ctx, mbrt_text_fn fn, void* user);
/* Instead of a motion sink: the context keeps every motion of a run (on =
 * 1), read with mbrt_buffered_motions. */
void mbrt_buffer_motions(mbrt_ctx* ctx, int on);
/* The motions buffered since the run started (mbrt_start and mbrt_run_main
 * empty the buffer); valid until the next run or mbrt_destroy. */
const mbrt_motion* mbrt_buffered_motions(const mbrt_ctx* ctx, size_t* count);
/* Blocks a run may execute before alarm MBC0002 (0 = the default limit). */
void mbrt_set_max_blocks(mbrt_ctx* ctx, uint64_t max_blocks);
/* Bytes of output a run may write before alarm MBC0003 (0 = the default,
 * 1 GiB). Counted: what the runtime sends to the print, message, trace and
 * flattened-program sinks, and sizeof(mbrt_motion) for each buffered motion;
 * a motion sink that writes the motions somewhere reports its bytes with
 * mbrt_count_output. The block whose output passes the limit completes and
 * the run stops before the next one, with the alarm at that block. */
void mbrt_set_max_output(mbrt_ctx* ctx, uint64_t max_bytes);
void mbrt_count_output(mbrt_ctx* ctx, uint64_t bytes);
/* Stops the run before its next block with alarm MBC0004 (INTERRUPTED).
 * The one call that may come from a signal handler or from another thread
 * while the run goes on; the next run (mbrt_start) is not interrupted. */
void mbrt_interrupt(mbrt_ctx* ctx);
/* Stops the run before its next block with alarm MBC0005 (OUT OF MEMORY):
 * for a new-handler that found the memory exhausted and freed a reserve, so
 * that the block going on can end and the run stop in order. May come from
 * another thread, as mbrt_interrupt. */
void mbrt_out_of_memory(mbrt_ctx* ctx);

/* ---- Profile settings engines need --------------------------------------
 */

/* A parameter of the machine profile (its default when the profile does not
 * set it; 0 for a number mbc does not model, docs/machine-profile.md). */
double mbrt_parameter(const mbrt_ctx* ctx, int number);
/* 1 when the profile turns the optional block skip switch on: blocks
 * starting with '/' are skipped. */
int mbrt_block_skip(const mbrt_ctx* ctx);
/* Turns optional block skip switches on: bit n for /n (bit 1 for plain '/'),
 * on top of the profile's switch. */
void mbrt_set_block_skip(mbrt_ctx* ctx, unsigned mask);
/* 1 when switch /n is on (the profile's switch counts as /1). */
int mbrt_skip_switch(const mbrt_ctx* ctx, int n);

/* ---- Execution bookkeeping ----------------------------------------------
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

/* ---- Variables -----------------------------------------------------------
 */

/* #[number]: the number is rounded half away from zero, then range-checked
 * (PS0115). Reads give vacant for unset variables. */
mbrt_status mbrt_read_var(mbrt_ctx* ctx, double number, mbrt_num* out);
/* #[number] = value. comment is the block's (MESSAGE) text for #3000/#3006
 * (may be NULL). Read-only variables give PS0116. */
mbrt_status mbrt_write_var(mbrt_ctx* ctx, double number, mbrt_num value,
                           const char* comment);
/* #[number] = value from outside the program (mbc run --set, a batch
 * table's #N column): as mbrt_write_var, but the input signals #1000-#1031
 * (0 or 1) and #1032-#1035 (32-bit words), which programs only read, take
 * the value as the PMC would set them. */
mbrt_status mbrt_preset_var(mbrt_ctx* ctx, double number, mbrt_num value);
/* ADP[#number]: a local set from a macro argument written without decimal
 * point gets its decimal point back (X10 -> 0.010 -> 10.0). */
mbrt_status mbrt_adp(mbrt_ctx* ctx, double number, mbrt_num* out);
/* A common variable (#100..#999, #98000..#98499) without side effects: 1
 * and *out when the number is a common variable of this machine, else 0. */
int mbrt_peek_common(const mbrt_ctx* ctx, int number, mbrt_num* out);
/* How many tool offsets the machine has (#10001.. up to #10000 + count). */
int mbrt_tool_offset_count(const mbrt_ctx* ctx);

/* ---- Words, NC blocks and calls ------------------------------------------
 */

enum mbrt_word_kind {
  MBRT_WORD_INT_LITERAL = 0, /* "X10": least-increment units on axes */
  MBRT_WORD_DEC_LITERAL = 1, /* "X10." */
  MBRT_WORD_VALUE = 2        /* a variable or [expression]: a real value */
};

/* One evaluated address word. A word whose value was a bare vacant variable
 * is not passed at all (spec §2.3a). */
typedef struct mbrt_word {
  char letter;
  unsigned char kind; /* mbrt_word_kind */
  double value;
} mbrt_word;

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

typedef struct mbrt_flow {
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
} mbrt_flow;

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

/* ---- Compiled programs ---------------------------------------------------
 */

/* A body returns this when the run ended (M02/M30, M99 or the end of the
 * main program's text; mbrt_finish was called). */
#define MBRT_STOP (-1)

/* The code of one program, run at the current call level. Returns 0 when it
 * leaves by M99 or the end of its text (leave->has_seq/seq tell M99 P),
 * MBRT_STOP, or an alarm. user is the engine's. */
typedef mbrt_status (*mbrt_body_fn)(mbrt_ctx* ctx, void* user,
                                    mbrt_flow* leave);

typedef struct mbrt_program {
  const char* name; /* "O1000", "<NAME>" or "MAIN" */
  int number;       /* O number; from 100000000 up for named programs (calls by
                     * name carry it); -1 for an anonymous main program */
  mbrt_body_fn body;
} mbrt_program;

/* The programs of one compiled object (`mbc compile --header` names it). */
typedef struct mbrt_program_table {
  const mbrt_program* programs;
  size_t count;
} mbrt_program_table;

/* The program with this number or name ("O1000" also finds number 1000,
 * "DRILL" finds <DRILL>); NULL when there is none. */
const mbrt_program* mbrt_find_program(const mbrt_program_table* table,
                                      int number, const char* name);

/* Tells the context the names of the table's programs called by name, so
 * that traces show `M98 <DRILL>` rather than the number the call carries.
 * Entry points and `mbc` call it before a run; the names are copied. */
void mbrt_name_programs(mbrt_ctx* ctx, const mbrt_program_table* table);

/* A call of `body` (kind: mbrt_call_kind), `repeat` times (none when <= 0):
 * each time mbrt_call, the body, the return; an M99 P stops the repetitions
 * and is passed on in out->has_seq/seq. */
mbrt_status mbrt_run_call(mbrt_ctx* ctx, const char* program, int kind,
                          const mbrt_word* args, size_t count, long repeat,
                          mbrt_body_fn body, void* user, mbrt_flow* out);

/* Runs a program as the main program from the current state (after
 * mbrt_start and any variable presets): 0 or the alarm that stopped it. */
mbrt_status mbrt_run_body(mbrt_ctx* ctx, const mbrt_program* program);
/* mbrt_start, the arguments into #1..#33 as G65 would pass them, then
 * mbrt_run_body: one call of a compiled cycle. */
mbrt_status mbrt_run_main(mbrt_ctx* ctx, const mbrt_program* program,
                          const mbrt_word* args, size_t count);
/* The machine back to power-on: modal codes, the tool at the machine
 * origin, no G92/G52/mirror/scaling/rotation/tool length offset, the clock
 * (#3001) at 0, no alarm. Machine data (commons, offsets, part counters),
 * sinks and limits stay. */
void mbrt_reset_state(mbrt_ctx* ctx);
/* Back to the state mbrt_create gave: mbrt_reset_state, and commons,
 * offsets and part counters from the profile. Sinks and limits stay. */
void mbrt_reset(mbrt_ctx* ctx);

/* ---- Output statements ---------------------------------------------------
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

/* ---- Alarms and results --------------------------------------------------
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
/* PS0076 "O<number>": a called program that does not exist (PS0074 when
 * the number has more digits than the machine's program numbers). */
mbrt_status mbrt_raise_program_not_found(mbrt_ctx* ctx, double number);
/* The pending alarm id, or 0. */
int mbrt_alarm(const mbrt_ctx* ctx);
/* The pending alarm's number as the control shows it: 112 for PS0112, 3001
 * for #3000=1, 2 for mbc's MBC0002; 0 when none is pending. */
int mbrt_alarm_number(const mbrt_ctx* ctx);
/* Its code: "PS0112", "3001", "MBC0002" ("" when none is pending); returns
 * the length (snprintf-style). */
size_t mbrt_alarm_code(const mbrt_ctx* ctx, char* buf, size_t size);
/* "file:line: alarm PS0112: ZERO DIVIDE" plus one "  in O9100 called from
 * file:line" line per call level, innermost first, each line ending in '\n'
 * (empty when no alarm is pending); returns the length (snprintf-style). */
size_t mbrt_alarm_report(const mbrt_ctx* ctx, char* buf, size_t size);

typedef struct mbrt_stats {
  uint64_t blocks;
  uint64_t moves;
  uint64_t optional_stops; /* M00/M01 met (the run went on) */
  int main_m99;            /* the run ended by M99 in the main program */
  /* The toolpath, in `unit`: "mm", or "inch" when the profile's unit is */
  const char* unit;
  double feed_length;  /* path length of feed moves */
  double rapid_length; /* and of rapids */
  double cycle_time; /* seconds: feeds at F, rapids at the rapid rate, dwells */
  int axis_count;    /* the bounding box of the workpiece coordinates, */
  const char* axis_names; /* arcs included (when moves > 0) */
  double box_min[MBRT_MAX_AXES];
  double box_max[MBRT_MAX_AXES];
} mbrt_stats;

void mbrt_get_stats(const mbrt_ctx* ctx, mbrt_stats* out);

#ifdef __cplusplus
}
#endif

#endif /* MBC_RUNTIME_H */
