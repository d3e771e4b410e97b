; RUN: %mbc compile %s -o - --emit=llvm -O0 | FileCheck %s
; The block state's file is stored by the first begin of a program and by
; the first after a call (the callee's begins stored its own file), not by
; every begin: nothing else writes it.
#1 = 1
#2 = 2
G65 P9100
#3 = 3
M30
O9100
M99
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK: store ptr @[[FILE:[.a-z0-9]+]], ptr [[SLOT:%[0-9]+]]
; CHECK-NEXT: store i32 5, ptr
; CHECK-NOT: store ptr @[[FILE]]
; CHECK: store ptr @[[FILE]], ptr [[SLOT]]
; CHECK-NEXT: store i32 8, ptr
; CHECK-NOT: store ptr @[[FILE]]
; CHECK: store i32 6, ptr
; CHECK-NOT: store ptr @[[FILE]]
; CHECK: store i32 7, ptr
; CHECK-NOT: store ptr @[[FILE]]
; CHECK: call i32 @mbc.call(
; CHECK-NOT: store ptr @[[FILE]]
; CHECK: {{^}}}
