; RUN: %mbc emit-ir %s | FileCheck %s
; RUN: %mbc emit-ir --disable-pass cse %s | FileCheck %s --check-prefix=OFF
; RUN: %mbc emit-ir %s | FileCheck %s --check-prefix=ARMS
; The same computation twice: the second takes the first's value when the
; first dominates it, in the same block or an earlier one (constants match
; by value, and #101 + #100 is #100 + #101). In the two arms of the IF
; neither dominates the other, so each keeps its own SQRT.
#100 = #1 * 2
IF [#2 GT 0] GOTO 10
#101 = SQRT[#100 + 1]
GOTO 20
N10 #101 = SQRT[#100 + 1] + 5
N20 #102 = #1 * 2 + [#101 + #100] * [#100 + #101]
M30
; CHECK-LABEL: func @MAIN
; CHECK: [[M:%[0-9]+]] = mul
; CHECK: begin 13
; CHECK-NEXT: [[L:%[0-9]+]] = ldvar #101
; CHECK-NEXT: [[T:%[0-9]+]] = tonum [[L]]{{$}}
; CHECK-NEXT: [[S:%[0-9]+]] = add [[T]], [[M]]{{$}}
; CHECK-NEXT: [[SQ:%[0-9]+]] = mul [[S]], [[S]]{{$}}
; CHECK-NEXT: add [[M]], [[SQ]]{{$}}
; ARMS-COUNT-2: fn SQRT
; ARMS-NOT: fn SQRT
; OFF-LABEL: func @MAIN
; OFF: begin 13
; OFF-NEXT: tonum
; OFF-NEXT: const 2
; OFF-NEXT: mul
; OFF-NEXT: [[L:%[0-9]+]] = ldvar #101
; OFF-NEXT: tonum [[L]]{{$}}
; OFF-NEXT: add
; OFF-NEXT: tonum [[L]]{{$}}
