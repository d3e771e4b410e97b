/* The mbc runtime as an embedder uses it (C ABI): a context is one machine
 * (a control with its profile, variables, offsets, position and modal
 * state); programs compiled by `mbc compile` run on it, and what they do
 * comes out through sinks or the motion buffer. mbc/engine.h is the rest
 * of the runtime, what engines and generated code call.
 *
 * Ownership: the caller owns a context from mbrt_create to mbrt_destroy.
 * Strings passed in are copied or only read during the call, except a sink's
 * `user` pointer, which the context keeps until the sink is replaced.
 * Pointers handed out (buffered motions, the names in a motion or in the
 * statistics) stay valid until the next run starts or the context is
 * destroyed.
 *
 * Threads: contexts are independent (no globals), so each thread may run
 * its own; one context is used by one thread at a time. mbrt_interrupt and
 * mbrt_out_of_memory are the only calls that may come from another thread
 * or a signal handler while a run goes on.
 *
 * Reentrancy: sinks are called in the middle of a block. From inside one, a
 * call that would start, reset or free the context is refused (see the
 * sink types below); reading variables and the statistics is allowed.
 *
 * Every fallible call returns an mbrt_status: MBRT_OK to go on, otherwise
 * the alarm that stopped the run. The context keeps the alarm, its message
 * and the block (file:line) it happened in; mbrt_alarm_report formats it.
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

/* A variable's value: an IEEE double, or vacant (a reserved NaN:
 * mbrt_vacant, mbrt_is_vacant). */
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
  /* Bit n: axis n is programmed and shown as a diameter (a lathe's X):
   * its coordinates and centre are diameters, twice the distance from the
   * spindle axis that the geometry of the move follows. */
  unsigned diameter_mask;
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
/* A motion sink that hands its motions to a thread of its own may count
 * an upper bound of each one's bytes. When the count passes the limit the
 * runtime calls `settle`, which waits until the thread has written what
 * it holds and returns how many of the bytes counted were over the exact
 * ones; the limit is then checked on the exact count. Called on the run's
 * thread, from inside mbrt_count_output. */
typedef uint64_t (*mbrt_settle_fn)(void* user);
void mbrt_set_output_settle(mbrt_ctx* ctx, mbrt_settle_fn fn, void* user);
/* Stops the run before its next block with alarm MBC0004 (INTERRUPTED).
 * The one call that may come from a signal handler or from another thread
 * while the run goes on; the next run (mbrt_start) is not interrupted. */
void mbrt_interrupt(mbrt_ctx* ctx);
/* Stops the run before its next block with alarm MBC0005 (OUT OF MEMORY):
 * for a new-handler that found the memory exhausted and freed a reserve, so
 * that the block going on can end and the run stop in order. May come from
 * another thread, as mbrt_interrupt. */
void mbrt_out_of_memory(mbrt_ctx* ctx);

/* Turns optional block skip switches on: bit n for /n (bit 1 for plain '/'),
 * on top of the profile's switch. */
void mbrt_set_block_skip(mbrt_ctx* ctx, unsigned mask);

/* ---- Variables -----------------------------------------------------------
 */

/* Vacant, the value of #0 and of an unset variable: writing it unsets a
 * variable. */
mbrt_num mbrt_vacant(void);
/* 1 when v is vacant (every NaN is: arithmetic never gives one), else 0. */
int mbrt_is_vacant(mbrt_num v);

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
/* A common variable (#100..#999, #98000..#98499) without side effects: 1
 * and *out when the number is a common variable of this machine, else 0. */
int mbrt_peek_common(const mbrt_ctx* ctx, int number, mbrt_num* out);
/* The common variables that are set (not vacant), in number order: up to
 * `capacity` of them into numbers[] and values[]; returns how many there
 * are (snprintf-style: call with capacity 0 to size the arrays). */
size_t mbrt_set_commons(const mbrt_ctx* ctx, int* numbers, mbrt_num* values,
                        size_t capacity);
/* How many tool offsets the machine has (#10001.. up to #10000 + count). */
int mbrt_tool_offset_count(const mbrt_ctx* ctx);

/* ---- The offset memory in the machine's unit ------------------------------
 * Work and tool offsets by the names of the machine profile's
 * "work_offsets" and "tool_offsets": a work offset set ("EXT", "G54".."G59",
 * "G54.1P1".."G54.1P300") and an axis in profile order; a tool offset's
 * number and field ("h_geometry", "h_wear", "d_geometry", "d_wear" as the
 * offset memory type has them; a lathe's "x_wear", "z_wear", "y_wear",
 * "r_wear", "tip" and with geometry and wear memory "x_geometry"...).
 * Work offsets are in the machine's unit (the profile's "units"; degrees on
 * a rotary axis, a diameter on a lathe's X) whatever G20/G21 a run left in
 * force; tool offsets are the numbers the memory holds (G20/G21 do not
 * convert them). This is what `mbc run --state` saves and loads. Each
 * returns 1, or 0 for a name, number or axis the machine does not have or
 * a value it cannot hold (more than nine digits; a tip other than 0-9).
 * A write of the work offset in force keeps the machine position, as
 * writing #5221+ does. */
int mbrt_get_work_offset(const mbrt_ctx* ctx, const char* set, int axis,
                         double* value);
int mbrt_set_work_offset(mbrt_ctx* ctx, const char* set, int axis,
                         double value);
int mbrt_get_tool_offset(const mbrt_ctx* ctx, int number, const char* field,
                         double* value);
int mbrt_set_tool_offset(mbrt_ctx* ctx, int number, const char* field,
                         double value);
/* The names to go through: the i-th work offset set (0, 1, ...) and the
 * i-th field of this machine's tool offsets, NULL past the last. */
const char* mbrt_work_offset_set(int i);
const char* mbrt_tool_offset_field(const mbrt_ctx* ctx, int i);

/* ---- The machine position -------------------------------------------------
 * Where the tool stands, per axis in profile order, in machine coordinates
 * and the machine's unit (as work offsets above: the profile's "units",
 * degrees on a rotary axis, a diameter on a lathe's X), what #5021+ read.
 * A run starts where the last left the tool; mbrt_set_machine_position
 * puts it elsewhere between runs, as jogging the machine does (the work
 * coordinates #5041+ follow; nothing moves, nothing is drawn). Each
 * returns 1, or 0 for an axis the machine does not have, a value it cannot
 * hold (more than nine digits, not finite) or a call from inside a sink. */
int mbrt_get_machine_position(const mbrt_ctx* ctx, int axis, double* value);
/* The stored stroke of an axis (parameters 1320/1321), in the machine's
 * unit as above: 1 with its ends in low and high when the run's check
 * holds the axis, 0 when the axis has none (1320 below 1321, or it rolls
 * over) or does not exist. */
int mbrt_get_stroke(const mbrt_ctx* ctx, int axis, double* low, double* high);
int mbrt_set_machine_position(mbrt_ctx* ctx, int axis, double value);

/* ---- Programs and their arguments ----------------------------------------
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

/* What a program leaves with (mbc/engine.h). */
typedef struct mbrt_flow mbrt_flow;

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

/* mbrt_start, the arguments into #1..#33 as G65 would pass them (a letter
 * in either case: 'x' is X), then mbrt_run_body (mbc/engine.h): one call
 * of a compiled cycle, from the machine state the last run left. A letter
 * that is no argument (G L N O P) is alarm PS0125, called by the host. */
mbrt_status mbrt_run_main(mbrt_ctx* ctx, const mbrt_program* program,
                          const mbrt_word* args, size_t count);
/* The machine back to power-on: modal codes, the tool at the machine
 * origin, no G92/G52/mirror/scaling/rotation/tool length offset, the output
 * signals (#1100+) off, the clock (#3001) at 0, no alarm. Machine data
 * (commons, offsets, part counters, #3002, #3005), sinks and limits stay. */
void mbrt_reset_state(mbrt_ctx* ctx);
/* Back to the state mbrt_create gave, all of it (commons, offsets, part
 * counters, #3002, settings, signals from the profile): runs after it see
 * nothing of runs before. What the host set stays: sinks, limits, block
 * skip switches, motion buffering and the names of loaded programs. */
void mbrt_reset(mbrt_ctx* ctx);

/* ---- Alarms and results --------------------------------------------------
 */

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
/* The report's parts, for a host that shows them its own way: the message
 * after the code ("ZERO DIVIDE", "ILLEGAL ARGUMENT: SQRT[-1]", a #3000
 * message; snprintf-style), the block it happened in ("" and 0 when none is
 * pending), and the calls it happened under, innermost first, one per "in
 * O9100 called from file:line" line: level < mbrt_alarm_depth gives 1 with
 * the program called and the calling block, otherwise 0. The strings stay
 * valid until the next run. */
size_t mbrt_alarm_message(const mbrt_ctx* ctx, char* buf, size_t size);
const char* mbrt_alarm_file(const mbrt_ctx* ctx);
int mbrt_alarm_line(const mbrt_ctx* ctx);
size_t mbrt_alarm_depth(const mbrt_ctx* ctx);
int mbrt_alarm_call(const mbrt_ctx* ctx, size_t level, const char** program,
                    const char** file, int* line);

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
