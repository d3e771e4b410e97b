; RUN: %mbc compile %s -o - --emit=llvm | FileCheck %s
; A promoted loop: the counter and the sum are phis, so the body reads and
; writes no variable through the runtime; the product is made non-negative
; zero (x + 0.0) as mbc/arith.h does.
#1 = 0
#2 = 0
WHILE [#1 LT 1000] DO1
#2 = #2 + #1 * 2
#1 = #1 + 1
END1
#100 = #2
M30
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK-NOT: @mbrt_read_var
; CHECK-NOT: @mbrt_write_var
; CHECK: phi double
; CHECK-NOT: @mbrt_read_var
; CHECK-NOT: @mbrt_write_var
; CHECK: [[PRODUCT:%[0-9]+]] = fmul double %{{[0-9]+}}, 2.000000e+00
; CHECK-NEXT: fadd double [[PRODUCT]], 0.000000e+00
; CHECK-NOT: @mbrt_read_var
; CHECK-NOT: @mbrt_write_var
; CHECK: {{^}}}
