; RUN: %mbc emit-ir --no-opt %s | FileCheck %s
; Every call of a program shares its one M99 P landing: the IR stays linear
; in calls plus N numbers instead of one case table per call.
O1000
N1 G65 P2000
N2 G65 P2000
N3 M98 P2000
N4 M30
O2000
M99 P4
; CHECK-LABEL: func @O1000 #1000
; CHECK: call.macro
; CHECK-NEXT: resume %{{[0-9]+}}, b{{[0-9]+}}, [[LAND:b[0-9]+]]{{$}}
; CHECK: call.macro
; CHECK-NEXT: resume %{{[0-9]+}}, b{{[0-9]+}}, [[LAND]]{{$}}
; CHECK: nc N:int %{{[0-9]+}}, M:int
; CHECK-NEXT: resume %{{[0-9]+}}, b{{[0-9]+}}, [[LAND]]{{$}}
; CHECK: [[LAND]]:
; CHECK-NEXT: [[S:%[0-9]+]] = retseq
; CHECK-NEXT: switch [[S]] [1: b1, 2: b2, 3: b3, 4: b4]
; CHECK-NOT: retseq
; CHECK-LABEL: func @O2000
