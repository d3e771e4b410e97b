// The main function of the executables `mbc build` links: the generated
// `main` passes its arguments and the program table here.
#pragma once

#include <mbc/runtime.h>

extern "C" int mbc_aot_main(int argc, char** argv,
                            const mbrt_program_table* table);
