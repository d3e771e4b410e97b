; RUN: %mbc compile -c %s -o %t.o --header %t.h
; RUN: FileCheck %s --check-prefix=HEADER < %t.h
; RUN: %mbc compile %s -o - --emit=asm | FileCheck %s --check-prefix=ASM
; RUN: %mbc compile %s -o %t.mbir --emit=ir
; RUN: %mbc compile -x mbir %t.mbir -o - --emit=llvm --table cycles | FileCheck %s --check-prefix=TABLE
; RUN: not %mbc compile %s 2>&1 | FileCheck %s --check-prefix=NO-OUTPUT
; RUN: not %mbc compile %s -o %t.x --emit=exe 2>&1 | FileCheck %s --check-prefix=BAD-EMIT
; RUN: not %mbc compile %s -o %t.o --table 9lives 2>&1 | FileCheck %s --check-prefix=BAD-TABLE
; RUN: %mbc compile %s -o %t.native.o --cpu native
; RUN: not %mbc compile %s -o %t.o --cpu bogus 2>&1 | FileCheck %s --check-prefix=BAD-CPU
; The outputs of mbc compile: an object and its header (the table is named
; after the output file), assembly, IR text that compiles again, an object
; for this machine's CPU, and the usage errors.
O0010
G65 P9100 A1
M30
O9100
#100 = #1
M99
; HEADER: #include <mbc/runtime.h>
; HEADER: extern const mbrt_program_table mbc_programs_compile_outputs_nc_tmp;
; HEADER: mbrt_status mbc_O10(mbrt_ctx* ctx, const mbrt_word* args, size_t count);
; HEADER: mbrt_status mbc_O9100(mbrt_ctx* ctx, const mbrt_word* args, size_t count);
; ASM: mbc_O9100:
; ASM: mbc_programs:
; TABLE: @cycles = {{.*}}constant %mbrt_program_table
; NO-OUTPUT: mbc: error: mbc compile needs -o OUTPUT
; BAD-EMIT: mbc: error: unknown --emit 'exe' (ir, llvm, asm or obj)
; BAD-TABLE: mbc: error: --table '9lives' is not a C identifier
; BAD-CPU: mbc: error: unknown CPU 'bogus' for {{.*}} (try native, or a name llc -mcpu=help lists)
