; RUN: %mbc emit-ir %s | FileCheck %s
; RUN: %mbc emit-ir %only-mem2ssa %s | FileCheck %s --check-prefix=ONLY
; A WHILE loop over locals: the counter and the sum become phis at the loop
; head, and no load or store of #1 or #2 is left inside the loop. They are
; stored back once, before `ret` (the end of the text returns to a caller
; that may share the frame). The M30 block cannot hand the frame to other
; code (only M98 and M99 can), so it needs no store. Both phis start at 0
; and only add numbers, so vacancy types them num and no tonum is left.
#1 = 0
#2 = 0
WHILE [#1 LT 10] DO1
#2 = #2 + #1
#1 = #1 + 1
END1
#100 = #2
M30
; CHECK-LABEL: func @MAIN
; CHECK: b1:
; CHECK-NEXT: [[I:%[0-9]+]] = phi num [[[ZERO:%[0-9]+]], b0], [[[NEXT:%[0-9]+]], b2]
; CHECK-NEXT: [[SUM:%[0-9]+]] = phi num [[[ZERO2:%[0-9]+]], b0], [[[ADD:%[0-9]+]], b2]
; CHECK-NOT: {{ldvar|stvar|tonum}}
; CHECK: condbr %{{[0-9]+}}, b2, b3
; CHECK: b2:
; CHECK-NOT: {{ldvar|stvar|tonum}}
; CHECK: [[ADD]] = add [[SUM]], [[I]]{{$}}
; CHECK-NOT: {{ldvar|stvar}}
; CHECK: [[NEXT]] = add [[I]], %{{[0-9]+}}
; CHECK-NOT: {{ldvar|stvar}}
; CHECK: br b1
; CHECK: b3:
; CHECK: stvar #100, [[SUM]]{{$}}
; CHECK-NOT: stvar
; CHECK: resume
; CHECK: stvar #1, [[I]] !16
; CHECK-NEXT: stvar #2, [[SUM]] !16
; CHECK-NEXT: ret
; ONLY-LABEL: func @MAIN
; ONLY: phi
; ONLY-NOT: ldvar #1
