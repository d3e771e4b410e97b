/* Runs the cycle of cycle.nc and prints the #100 it leaves. */
#include "cycle.h"

#include <stdio.h>

int main(void) {
  char err[256];
  mbrt_num value = 0;
  mbrt_ctx* ctx = mbrt_create(NULL, err, sizeof err);
  if (ctx == NULL || mbc_O1(ctx, NULL, 0) != MBRT_OK ||
      mbrt_read_var(ctx, 100, &value) != MBRT_OK) {
    return 1;
  }
  printf("%g\n", value);
  mbrt_destroy(ctx);
  return 0;
}
