; RUN: %mbc emit-ir %s | FileCheck %s
; mem2ssa promotes a local unless an indirection may reach it, and the
; range analysis bounds the numbers: in O1000 #1 runs over 0..3, so
; #[#1 + 10] writes #10..#13 and never #1, which becomes a phi. In O2000 the
; index is an argument and may be any local: every local stays in memory.
; In O3000 the index #1 + 1 reaches #1 itself, so #1 stays in memory and,
; loaded from memory, bounds nothing: nothing is promoted.
O1000
#1 = 0
WHILE [#1 LT 3] DO1
#[#1 + 10] = #1
#1 = #1 + 1
END1
M99
O2000
#2 = 5
#[#1] = #2
#3 = #2
M99
O3000
#1 = 0
WHILE [#1 LT 3] DO1
#[#1 + 1] = 2
#1 = #1 + 1
END1
M99
; CHECK-LABEL: func @O1000
; CHECK: b1:
; CHECK-NEXT: [[I:%[0-9]+]] = phi num
; CHECK-NOT: {{ldvar|stvar}}
; CHECK: [[N:%[0-9]+]] = add [[I]], %{{[0-9]+}}
; CHECK-NEXT: stind [[N]], [[I]]{{$}}
; CHECK-NOT: ldvar
; CHECK: stvar #1, [[I]]{{$}}
; CHECK-NEXT: resume
; CHECK-LABEL: func @O2000
; CHECK: stvar #2,
; CHECK: ldvar #1
; CHECK: stind
; CHECK: ldvar #2
; CHECK: stvar #3,
; CHECK-LABEL: func @O3000
; CHECK-NOT: phi
; CHECK: stvar #1,
; CHECK: ldvar #1
; CHECK: stind
; CHECK: ldvar #1
; CHECK: stvar #1,
