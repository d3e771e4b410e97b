; RUN: %mbc emit-ir %s | FileCheck %s
; An indirect store may write any local, so the function keeps every local
; in memory: the loop still loads and stores #1. The other program has no
; indirection and is promoted on its own.
O1000
#1 = 0
WHILE [#1 LT 3] DO1
#[#1 + 10] = #1
#1 = #1 + 1
END1
M99
O2000
#1 = 5
#2 = #1 * 2
M99
; CHECK-LABEL: func @O1000
; CHECK: stvar #1,
; CHECK: ldvar #1
; CHECK: stind
; CHECK: ldvar #1
; CHECK: stvar #1,
; CHECK-LABEL: func @O2000
; CHECK-NOT: ldvar
; CHECK: [[FIVE:%[0-9]+]] = const 5
; CHECK: [[TWICE:%[0-9]+]] = const 10
; CHECK: stvar #1, [[FIVE]]{{$}}
; CHECK-NEXT: stvar #2, [[TWICE]]{{$}}
; CHECK-NEXT: resume
