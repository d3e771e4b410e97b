; RUN: rm -f %t.so
; RUN: %mbc compile --shared %s -o %t.so --header %t.h --table cycles -v 2>&1 | FileCheck %s --check-prefix=LINK
; RUN: nm -D --defined-only %t.so | FileCheck %s --check-prefix=EXPORTS
; RUN: FileCheck %s --check-prefix=HEADER < %t.h
; RUN: not %mbc compile --shared %s -o %t.so --emit=asm 2>&1 | FileCheck %s --check-prefix=BAD-EMIT
; RUN: not %mbc run --shared %s 2>&1 | FileCheck %s --check-prefix=BAD-COMMAND
; RUN: not %mbc compile --shared %s -o - 2>&1 | FileCheck %s --check-prefix=STDOUT
; RUN: env CXX=false not %mbc compile --shared %s -o %t.bad.so 2>&1 | FileCheck %s --check-prefix=NO-LINK
; RUN: not test -e %t.bad.so
; `mbc compile --shared`: a shared library of the programs and the whole
; runtime, for ctypes and dlopen users, exporting only the C ABI (the
; runtime's C++ symbols stay local); -v shows the link; a failed link
; leaves no file.
O9100
#100 = #1
M99
; LINK: -shared {{.*}}program.o -Wl,--whole-archive {{.*}}libmbc_runtime.a -Wl,--no-whole-archive -Wl,--version-script=
; EXPORTS: {{[DR]}} cycles
; EXPORTS: T mbc_O9100
; EXPORTS-NOT: _Z
; EXPORTS: T mbrt_create
; EXPORTS-NOT: _Z
; HEADER: extern const mbrt_program_table cycles;
; HEADER: mbrt_status mbc_O9100(
; BAD-EMIT: mbc: error: --shared writes a shared library, not --emit=asm
; BAD-COMMAND: mbc: error: '--shared' is not an option of mbc run (it is one of mbc compile)
; STDOUT: mbc: error: mbc compile --shared needs -o FILE.so
; NO-LINK: mbc: error: linking '{{.*}}.bad.so' failed (false exited with 1)
