; RUN: %mbc emit-ir --no-opt %s | FileCheck %s
; A WHILE loop becomes a conditional branch at its head and a back edge from
; END to the head; variables stay in memory before the passes run. A variable may be vacant,
; so the comparison reads it through tonum (vacant reads as 0).
#1 = 0
WHILE [#1 LT 3] DO1
#1 = #1 + 1
END1
M30
; CHECK-LABEL: func @MAIN
; CHECK: b0:
; CHECK-NEXT: br b1
; CHECK: b1:
; CHECK-NEXT: begin 5
; CHECK-NEXT: [[ZERO:%[0-9]+]] = const 0
; CHECK-NEXT: stvar #1, [[ZERO]]{{$}}
; CHECK-NEXT: br b2
; CHECK: b2:
; CHECK-NEXT: begin 6
; CHECK-NEXT: [[I:%[0-9]+]] = ldvar #1
; CHECK-NEXT: [[N:%[0-9]+]] = tonum [[I]]{{$}}
; CHECK-NEXT: [[THREE:%[0-9]+]] = const 3
; CHECK-NEXT: [[C:%[0-9]+]] = lt [[N]], [[THREE]]{{$}}
; CHECK-NEXT: condbr [[C]], b3, b5
; CHECK: b4:
; CHECK-NEXT: begin 8
; CHECK-NEXT: br b2
