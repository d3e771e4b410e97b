/* The part of the runtime's C ABI that only generated code uses (codegen/):
 * the storage it addresses directly so that locals, commons and the block
 * counter cost no call, and the operations it leaves to the runtime. Not for
 * embedders: runtime.h is their interface. Every call takes the context, so
 * compiled code stays thread-independent.
 */
#ifndef MBC_COMPILED_H
#define MBC_COMPILED_H

#include <mbc/direct_storage.h>
#include <mbc/engine.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The current call level. Levels never move (the runtime reserves them for
 * the deepest nesting), so the pointer stays valid while this level exists. */
mbrt_level* mbrt_current_level(mbrt_ctx* ctx);
/* Element n is common variable #n (100..199 and 500..999 always exist, 200..
 * 499 only on machines with the extended set). Valid for the context's
 * lifetime. */
mbrt_num* mbrt_common_base(mbrt_ctx* ctx);
mbrt_block_state* mbrt_block_state_of(mbrt_ctx* ctx);
/* Raises MBC0002 for the block just counted past the limit. */
mbrt_status mbrt_block_limit(mbrt_ctx* ctx);

/* A run of NC blocks whose words are all constants, which a posted part
 * program is made of, packed as data. Step i is line steps[3i], with
 * steps[3i+1] words from word steps[3i+2]; word j is letter codes[2j],
 * mbrt_word_kind codes[2j+1] and value values[j]. */
typedef struct mbrt_nc_run {
  const char* file;
  const int32_t* steps;
  const uint8_t* codes;
  const double* values;
  size_t count; /* steps */
} mbrt_nc_run;

/* Executes the steps of a run from step `first` on, each as
 * mbrt_begin_block and mbrt_nc_block, until one raises an alarm (its status
 * is returned) or gives a flow other than going on to the next block (in
 * *flow, for mbc.resume). *next: the step after the last one begun. One call
 * instead of code per block keeps the compile time of a posted program of a
 * million blocks linear and small. */
mbrt_status mbrt_nc_steps(mbrt_ctx* ctx, const mbrt_nc_run* run, size_t first,
                          mbrt_flow* flow, size_t* next);

/* a op b for the operations of mbc/arith.h's BinOp, and the builtins of
 * mbc/builtins.def (in their order), with the profile's NAT bit; an alarm is
 * raised and returned. */
mbrt_status mbrt_binary(mbrt_ctx* ctx, int op, double a, double b, double* out);
mbrt_status mbrt_builtin(mbrt_ctx* ctx, int builtin, double a, double b,
                         double* out);
/* ROUND written directly in an address: to the letter's least increment. */
mbrt_status mbrt_round_address(mbrt_ctx* ctx, int letter, double x,
                               double* out);

#ifdef __cplusplus
}
#endif

#endif /* MBC_COMPILED_H */
