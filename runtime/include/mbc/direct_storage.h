/* The storage that generated code addresses directly, so that locals and
 * the block counter cost no call (compiled.h gives it the pointers). The
 * runtime's context holds it.
 */
#ifndef MBC_DIRECT_STORAGE_H
#define MBC_DIRECT_STORAGE_H

#include <mbc/runtime.h>

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One call level's #1..#33. Bit i of adp_mask: #(i+1) was set from an
 * argument written without decimal point (ADP gives the literal back); a
 * program's own write clears it. */
typedef struct mbrt_level {
  mbrt_num value[33];
  uint64_t adp_mask;
} mbrt_level;

/* What mbrt_begin_block keeps: generated code does the same inline and calls
 * mbrt_block_limit once `blocks` passes `max_blocks`. `tracing` is 1 while a
 * trace sink is set: compiled trace statements test it first. */
typedef struct mbrt_block_state {
  const char* file;
  int line;
  int tracing;
  uint64_t blocks;
  uint64_t max_blocks;
} mbrt_block_state;

#ifdef __cplusplus
}
#endif

#endif
