; RUN: %mbc emit-ir %s | FileCheck %s
; A common's known value flows into later blocks when every path brings the
; same value: #100 is 5 in both arms of the IF and where they join. A
; call runs other code that may change #100: after it, #100 is loaded.
; (A block with an N number is also where a called program's M99 P may
; come back, so nothing is known there after a call.)
#100 = 5
IF [#1 GT 0] THEN #101 = #100 + 1
#102 = #100
G65 P2000
#103 = #100
M30
O2000
#100 = 7
M99
; CHECK-LABEL: func @MAIN
; CHECK: b0:
; CHECK: [[FIVE:%[0-9]+]] = const 5
; CHECK-NEXT: stvar #100, [[FIVE]]{{$}}
; CHECK: b1:
; CHECK-NEXT: begin 9
; CHECK-NEXT: stvar #102, [[FIVE]]{{$}}
; CHECK: call.macro
; CHECK-NEXT: resume
; CHECK: [[L:%[0-9]+]] = ldvar #100
; CHECK-NEXT: stvar #103, [[L]]{{$}}
; CHECK: b4:
; CHECK-NEXT: [[SIX:%[0-9]+]] = const 6
; CHECK-NEXT: stvar #101, [[SIX]] !8
