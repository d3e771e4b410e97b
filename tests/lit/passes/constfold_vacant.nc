; RUN: %mbc emit-ir %s 2>/dev/null | FileCheck %s
; Folding follows the FANUC vacant rules (mbc/arith.h): #0 + 1 is 1 since
; vacant reads as 0 in arithmetic, but #0 EQ 0 is false (EQ tells vacant
; from 0), so that IF never jumps. 1/0 alarms (PS0112) when its block runs,
; so it stays an instruction, and so does the read of #50, which may not
; exist (PS0115).
#1 = #0 + 1
IF [#0 EQ 0] GOTO 9
#100 = #1
#101 = 1 / 0
#2 = #50
N9 #102 = #0
M30
; CHECK-LABEL: func @MAIN
; CHECK: begin 7
; CHECK-NEXT: [[ONE:%[0-9]+]] = const 1
; CHECK-NEXT: begin 8
; CHECK-NEXT: begin 9
; CHECK-NEXT: stvar #100, [[ONE]]{{$}}
; CHECK-NEXT: begin 10
; CHECK-NEXT: [[A:%[0-9]+]] = const 1
; CHECK-NEXT: [[Z:%[0-9]+]] = const 0
; CHECK-NEXT: [[Q:%[0-9]+]] = div [[A]], [[Z]]{{$}}
; CHECK-NEXT: stvar #101, [[Q]]{{$}}
; CHECK-NEXT: begin 11
; CHECK-NEXT: ldvar #50
; CHECK: begin 12
; CHECK-NEXT: [[V:%[0-9]+]] = vacant
; CHECK-NEXT: stvar #102, [[V]]{{$}}
