// Built into every executable that links the driver, under -DMBC_SANITIZE
// only (driver/CMakeLists.txt). GCC 12's LeakSanitizer follows the dynamic
// TLS of libraries loaded with dlopen (the code generator plugin and
// libLLVM) through __tls_get_addr, reads a garbage range for one of them
// and its tracer crashes at exit ("Tracer caught signal 11"), depending on
// the heap's layout. Not tracking that TLS can only report more leaks,
// never fewer.
extern "C" const char* __asan_default_options() {
  return "intercept_tls_get_addr=0";
}
