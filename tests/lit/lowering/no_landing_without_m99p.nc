; RUN: %mbc emit-ir %s | FileCheck %s
; No block of the unit is an M99 P, so no call can come back at an N of
; its caller: a calling block goes on to the next one alone, with no
; landing (a table of the N numbers per calling block when N numbers
; repeat, as CAM output that numbers each operation from N1 does, grew
; with the blocks times the N numbers).
O1000(TWO OPERATIONS)
N1G90G54G00X0.Y0.
N2M98P2000
N3G01X10.F300.
N1G00X20.
N2M98P2000
N3G01X30.
M30
O2000(SPOT)
G91G01Z-1.F100.
G90
M99
; CHECK-LABEL: func @O1000
; CHECK: nc {{.*}}M:int
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}} []
; CHECK: nc {{.*}}M:int
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}} []
; CHECK-NOT: retseq
; CHECK-LABEL: func @O2000
