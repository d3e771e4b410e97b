// libFuzzer target: any bytes as a machine-profile JSON document. mbrt_create
// either gives a context or an error message; it must never crash.
#include <mbc/engine.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  const std::string json(reinterpret_cast<const char*>(data), size);
  char error[512];
  if (mbrt_ctx* ctx = mbrt_create(json.c_str(), error, sizeof error)) {
    mbrt_start(ctx, "O1000");
    mbrt_destroy(ctx);
  }
  return 0;
}
