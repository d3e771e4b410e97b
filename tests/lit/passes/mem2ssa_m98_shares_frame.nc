; RUN: %mbc emit-ir %s | FileCheck %s
; M98 runs the subprogram on this frame: a local written before it is
; stored back before the resume of its NC block, and every local still
; needed is loaded again after it. A local written only on some paths is
; stored on those paths alone (a store resets its ADP state, so one more
; store would not be invisible). G65 gets a frame of its own: its resume
; neither stores nor loads.
O1000
#1 = 1
IF [#100 GT 0] THEN #2 = 5
M98 P2000
#101 = #1 + #2
G65 P2000 A1.
#102 = #1
M30
O2000
#1 = #1 + 1
M99
; CHECK-LABEL: func @O1000
; CHECK: b0:
; CHECK: [[ONE:%[0-9]+]] = const 1
; CHECK: condbr %{{[0-9]+}}, b5, b1
; CHECK: b1:
; CHECK: nc M:int %{{[0-9]+}}, P:int %{{[0-9]+}}
; CHECK-NEXT: stvar #1, [[ONE]]{{$}}
; CHECK-NEXT: resume
; CHECK: b2:
; CHECK-NEXT: [[R1:%[0-9]+]] = ldvar #1
; CHECK-NEXT: [[R2:%[0-9]+]] = ldvar #2
; CHECK-NEXT: begin 12
; CHECK-NEXT: [[N1:%[0-9]+]] = tonum [[R1]]{{$}}
; CHECK-NEXT: [[N2:%[0-9]+]] = tonum [[R2]]{{$}}
; CHECK-NEXT: add [[N1]], [[N2]]{{$}}
; CHECK: call.macro
; CHECK-NEXT: resume
; CHECK: b3:
; CHECK-NOT: ldvar #1
; CHECK: stvar #102, [[R1]]{{$}}
; CHECK-NOT: stvar #
; CHECK: resume
; CHECK: b5:
; CHECK: stvar #2, %{{[0-9]+}}
; CHECK-NEXT: br b1
