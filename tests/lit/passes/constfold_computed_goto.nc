; RUN: %mbc emit-ir %s | FileCheck %s
; RUN: %mbc emit-ir --no-opt %s | FileCheck %s --check-prefix=RAW
; A computed GOTO is a switch over every N of the program. With a known
; number it becomes a jump to that case (here #1 = 20 is known once #1 is
; promoted). A known number that has no case keeps the switch, since it
; alarms at run time (PS0128), and so does a number that is not known.
O1000
#1 = 20
GOTO #1
N10 #2 = 35
GOTO #2
N20 GOTO #100
N30 M30
; RAW-LABEL: func @O1000
; RAW: [[T:%[0-9]+]] = ldvar #1
; RAW-NEXT: switch [[T]] [10: b{{[0-9]+}}, 20: b{{[0-9]+}}, 30: b{{[0-9]+}}]
; CHECK-LABEL: func @O1000
; CHECK: begin 9
; CHECK-NOT: switch
; CHECK: br [[N20:b[0-9]+]]{{$}}
; CHECK: [[K:%[0-9]+]] = const 35
; CHECK-NEXT: begin 11
; CHECK-NEXT: switch [[K]] [10:
; CHECK: [[N20]]:
; CHECK-NEXT: begin 12
; CHECK-NEXT: [[U:%[0-9]+]] = ldvar #100
; CHECK-NEXT: switch [[U]] [10: b{{[0-9]+}}, 20: [[N20]], 30: b{{[0-9]+}}]
