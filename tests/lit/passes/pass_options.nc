; RUN: not %mbc emit-ir --disable-pass nosuchpass %s 2>&1 | FileCheck %s --check-prefix=BAD
; RUN: %mbc emit-ir --verify-each %s | FileCheck %s
; RUN: %mbc emit-ir --no-opt %s | FileCheck %s --check-prefix=RAW
; RUN: %mbc emit-ir --no-opt %s > %t.mbir
; RUN: %mbc emit-ir -x mbir %t.mbir | FileCheck %s
; The pass options: an unknown pass name is a usage error that lists the
; passes; --verify-each checks the IR after every pass; --no-opt prints the
; raw lowering, which -x mbir reads back and optimises like the source.
#1 = 2
#100 = #1 * 3
M30
; BAD: mbc: error: unknown pass 'nosuchpass' (passes: mem2ssa, copyprop, constfold, vacancy, cse, loadelim, dce, simplifycfg)
; BAD-NEXT: mbc: note: 'mbc emit-ir --help' lists its options
; CHECK-LABEL: func @MAIN
; CHECK: [[SIX:%[0-9]+]] = const 6
; CHECK-NEXT: stvar #100, [[SIX]]{{$}}
; RAW-LABEL: func @MAIN
; RAW: ldvar #1
; RAW: mul
