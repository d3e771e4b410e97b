; RUN: %mbc compile %s -o - --emit=llvm -O0 | FileCheck %s
; Writing a local by number clears its ADP flag; the writes of a run of
; statements clear theirs with one read-modify-write of the mask, before
; the next instruction that may read the flags or run code that may (here
; ADP[], and the return at the end of the program).
#1 = #100
#2 = #101 + 1
#3 = ADP[#1]
M30
; CHECK-LABEL: define internal i32 @mbc.body.MAIN(
; CHECK: store double %{{[0-9]+}}, ptr [[TWO:%[0-9]+]]
; CHECK: store double %{{[0-9]+}}, ptr [[THREE:%[0-9]+]]
; CHECK-NEXT: [[MASK:%[0-9]+]] = getelementptr inbounds %mbrt_level, ptr %level, i32 0, i32 1
; CHECK-NEXT: [[OLD:%[0-9]+]] = load i64, ptr [[MASK]]
; CHECK-NEXT: [[NEW:%[0-9]+]] = and i64 [[OLD]], -7
; CHECK-NEXT: store i64 [[NEW]], ptr [[MASK]]
; CHECK: [[MASK1:%[0-9]+]] = getelementptr inbounds %mbrt_level, ptr %level, i32 0, i32 1
; CHECK-NEXT: [[OLD1:%[0-9]+]] = load i64, ptr [[MASK1]]
; CHECK-NEXT: [[NEW1:%[0-9]+]] = and i64 [[OLD1]], -2
; CHECK-NEXT: store i64 [[NEW1]], ptr [[MASK1]]
; CHECK-NEXT: call i32 @mbrt_adp(
