/* An embedder written in C: runtime.h compiles as C99 with -Wpedantic, the
 * alarm of a run reads back as the control's number and code, and vacant
 * is written and told apart from 0 with runtime.h alone. */
#include <mbc/runtime.h>

#include <stdio.h>
#include <string.h>

int main(void) {
  char err[256];
  char code[16];
  mbrt_ctx* ctx = mbrt_create(NULL, err, sizeof err);
  mbrt_status status;
  int failures = 0;
  if (ctx == NULL) {
    fprintf(stderr, "mbrt_create: %s\n", err);
    return 1;
  }
  if (strcmp(mbrt_version(), MBC_VERSION_STRING) != 0) {
    fprintf(stderr, "library %s, header %s\n", mbrt_version(),
            MBC_VERSION_STRING);
    ++failures;
  }
  status = mbrt_write_var(ctx, 3000, 7.0, "TOOL TOO BIG");
  mbrt_alarm_code(ctx, code, sizeof code);
  if (status != MBRT_ALARM_MacroAlarm || mbrt_alarm_number(ctx) != 3007 ||
      strcmp(code, "3007") != 0) {
    fprintf(stderr, "#3000=7: status %d, number %d, code '%s'\n", status,
            mbrt_alarm_number(ctx), code);
    ++failures;
  }
  {
    mbrt_num value = 1.0;
    mbrt_ctx* fresh = mbrt_create(NULL, err, sizeof err);
    if (fresh == NULL || mbrt_write_var(fresh, 100, 0.0, NULL) != MBRT_OK ||
        mbrt_write_var(fresh, 101, mbrt_vacant(), NULL) != MBRT_OK ||
        mbrt_read_var(fresh, 100, &value) != MBRT_OK ||
        mbrt_is_vacant(value) || value != 0.0 ||
        mbrt_read_var(fresh, 101, &value) != MBRT_OK ||
        !mbrt_is_vacant(value) || !mbrt_is_vacant(mbrt_vacant())) {
      fprintf(stderr, "vacant: #100=0 and #101=vacant do not read back\n");
      ++failures;
    }
    mbrt_destroy(fresh);
  }
  mbrt_destroy(ctx);
  return failures == 0 ? MBRT_OK : 1;
}
