// Built only under MBC_SANITIZE: a heap overflow and a signed overflow that
// the sanitizers must report, so that `make test-asan` cannot pass with the
// checks silently off.
#include <cstdlib>
#include <cstring>
#include <memory>

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "heap") == 0) {
    auto bytes = std::make_unique<volatile char[]>(8);
    return bytes[argc + 7]; // past the end
  }
  volatile int big = 2147483647;
  return big + argc; // overflows for argc >= 1
}
