; RUN: %mbc emit-ir %s | FileCheck %s
; RUN: echo "G66 P9000" > %t.nc
; RUN: cat %s >> %t.nc
; RUN: %mbc emit-ir %t.nc | FileCheck %s --check-prefix=G66
; RUN: echo "G200 X0" > %t2.nc
; RUN: cat %s >> %t2.nc
; RUN: %mbc emit-ir %t2.nc | FileCheck %s --check-prefix=G66
; An NC block keeps its M99 P landing only when it may call a program: an M
; code other than M00/M01/M02/M30 (M98, or an M code subprogram of the
; profile), a T, S or B code, or a G code FANUC does not have (a custom G
; code, which may be modal as well). Plain motion drops it, unless some
; block of the module may start a modal call (G66, a custom G code): then
; every block may call. (O2000's M99 P10 makes the unit need landings at
; all: lowering/no_landing_without_m99p.nc.)
N10 G01 X1. F100.
M06
T1
G01 X3. M05
M30
O2000
M99P10
; CHECK-LABEL: func @MAIN
; CHECK: nc N:int {{.*}}, G:int {{.*}}, X:dec {{.*}}, F:dec
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}} []
; CHECK: nc M:int
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}}, b{{[0-9]+}}{{$}}
; CHECK: nc T:int
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}}, b{{[0-9]+}}{{$}}
; CHECK: nc G:int {{.*}}, X:dec {{.*}}, M:int
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}}, b{{[0-9]+}}{{$}}
; CHECK: nc M:int
; CHECK-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}} []
; G66-LABEL: func @MAIN
; G66: nc N:int {{.*}}, G:int {{.*}}, X:dec {{.*}}, F:dec
; G66-NEXT: resume {{%[0-9]+}}, b{{[0-9]+}}, b{{[0-9]+}}{{$}}
