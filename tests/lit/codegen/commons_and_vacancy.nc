; RUN: %mbc compile %s -o - --emit=llvm -O1 | FileCheck %s
; Commons are loads and stores at their number in the context's common
; array; #200..#499 depend on the machine and go through the runtime. EQ
; between two values that may both be vacant tests vacancy (fcmp uno);
; against a constant an ordered compare suffices.
#100 = #101 + 1
#300 = 5
IF [#1 EQ #2] THEN #102 = 1
IF [#3 EQ 7] THEN #103 = 1
M30
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK: [[SRC:%[0-9]+]] = getelementptr inbounds double, ptr %commons, i64 101
; CHECK: load double, ptr [[SRC]]
; CHECK: [[DST:%[0-9]+]] = getelementptr inbounds double, ptr %commons, i64 100
; CHECK: store double %{{[0-9]+}}, ptr [[DST]]
; CHECK: call i32 @mbrt_write_var(ptr %0, double 3.000000e+02, double 5.000000e+00, ptr null)
; CHECK: fcmp uno double
; CHECK: fcmp oeq double %{{[0-9]+}}, 7.000000e+00
