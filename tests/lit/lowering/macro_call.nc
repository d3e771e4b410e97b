; RUN: %mbc emit-ir --no-opt %s | FileCheck %s
; G65 becomes call.macro with P, L and the argument words; the resume after
; it goes on with the next block, or, after an M99 P of the callee, to the
; program's landing, which switches on the sequence number (retseq).
O1000
G65 P2000 L2 A1. B#1
N5 M30
O2000
M99 P5
; CHECK-LABEL: func @O1000 #1000
; CHECK: [[C:%[0-9]+]] = call.macro %{{[0-9]+}}, %{{[0-9]+}}, A:dec %{{[0-9]+}}, B:var %{{[0-9]+}}
; CHECK-NEXT: resume [[C]], b2, [[LAND:b[0-9]+]]{{$}}
; CHECK: [[LAND]]:
; CHECK-NEXT: [[S:%[0-9]+]] = retseq
; CHECK-NEXT: switch [[S]] [5: b2]
; CHECK-LABEL: func @O2000 #2000
; CHECK: nc M:int %{{[0-9]+}}, P:int %{{[0-9]+}}
