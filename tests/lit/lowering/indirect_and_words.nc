; RUN: %mbc emit-ir --no-opt %s | FileCheck %s
; #[e] is an indirect memory operation; NC words keep how they were written,
; so that vacant words drop and literals keep their decimal point meaning.
#[100 + #1] = #2 (STORED)
G01 X10 Y10. Z#3 A-#4 F[#5 * 2]
M30
; CHECK-LABEL: func @MAIN
; CHECK: [[V:%[0-9]+]] = ldvar #2
; CHECK: [[IDX:%[0-9]+]] = add
; CHECK-NEXT: stind [[IDX]], [[V]], "STORED"
; CHECK: [[F:%[0-9]+]] = nc G:int %{{[0-9]+}}, X:int %{{[0-9]+}}, Y:dec %{{[0-9]+}}, Z:var %{{[0-9]+}}, A:nvar %{{[0-9]+}}, F:val %{{[0-9]+}}
; CHECK-NEXT: resume [[F]], b3
