; RUN: %mbc emit-ir --no-opt %s | FileCheck %s
; A computed GOTO becomes a switch over every N of the program, each case the
; block the FANUC search reaches from the jump (forward, then from the top).
N10 #1 = 20
GOTO #1
N20 #2 = 1
N10 M30
; CHECK-LABEL: func @MAIN
; CHECK: [[T:%[0-9]+]] = ldvar #1
; CHECK-NEXT: switch [[T]] [10: b4, 20: b3]
