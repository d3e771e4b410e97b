// The version of the runtime library a program is linked with.
#include <mbc/runtime.h>

const char* mbrt_version(void) {
  return MBC_VERSION_STRING;
}
